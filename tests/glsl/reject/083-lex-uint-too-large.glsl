// rule: 4.1.3 Integers: an unsigned literal must fit in 32 bits
// error: '' : numeric literal too big
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    uint u = 4294967296u;
    fragColor = vec4(float(u));
}
