// rule: 4.1.4 Floats: an exponent needs digits (`1e` is not a literal)
// error: '' : bad character in float exponent
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float f = 1e;
    fragColor = vec4(f);
}
