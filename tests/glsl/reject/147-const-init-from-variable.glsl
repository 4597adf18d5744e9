// rule: 4.3.3 Constant Expressions: a non-const variable is not a constant expression
// error: 'non-constant initializer' : not supported with this profile: es
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float y = 1.0;
    const float x = y;
    fragColor = vec4(x);
}
