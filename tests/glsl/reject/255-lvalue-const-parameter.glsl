// rule: 4.4 Parameter Qualifiers: a const parameter cannot be written
// error: 'assign' : l-value required "x" (can't modify a const)
float f(const float x) {
    x = 2.0 * x;
    return x;
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(f(0.5));
}
