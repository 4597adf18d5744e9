// rule: 4.1.3 Integers: a hexadecimal literal must fit in 32 bits
// error: '' : hexadecimal literal too big
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    uint u = 0x100000000u;
    fragColor = vec4(float(u));
}
