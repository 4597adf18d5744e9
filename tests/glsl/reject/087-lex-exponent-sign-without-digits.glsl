// rule: 4.1.4 Floats: an exponent needs digits after its sign
// error: '' : bad character in float exponent
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float f = 2.0e+;
    fragColor = vec4(f);
}
