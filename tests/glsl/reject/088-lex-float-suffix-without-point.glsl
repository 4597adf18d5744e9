// rule: 4.1.4 Floats: a float literal needs a decimal point or an exponent, even with the f suffix
// error: '' : float literal needs a decimal point or exponent
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float f = 1f;
    fragColor = vec4(f);
}
