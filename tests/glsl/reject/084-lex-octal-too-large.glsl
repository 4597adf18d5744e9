// rule: 4.1.3 Integers: an octal literal must fit in 32 bits
// error: '' : octal literal too big
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    int i = 077777777777;
    fragColor = vec4(float(i));
}
