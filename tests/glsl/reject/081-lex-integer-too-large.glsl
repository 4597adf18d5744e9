// rule: 4.1.3 Integers: an integer literal must fit in 32 bits
// error: '' : numeric literal too big
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    int i = 4294967296;
    fragColor = vec4(float(i));
}
