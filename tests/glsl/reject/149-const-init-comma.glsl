// rule: 4.3.3 Constant Expressions: the sequence operator does not make a constant expression
// error: 'non-constant initializer' : not supported with this profile: es
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    const float g = (1.0, 2.0);
    fragColor = vec4(g);
}
