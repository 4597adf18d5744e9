// rule: 4.3.3 Constant Expressions: a call to a user function is not a constant expression
// error: 'non-constant initializer' : not supported with this profile: es
float half_of(float x) { return 0.5 * x; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    const float h = half_of(1.0);
    fragColor = vec4(h);
}
