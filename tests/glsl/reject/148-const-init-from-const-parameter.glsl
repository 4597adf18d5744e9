// rule: 4.3.3 Constant Expressions: a const-qualified parameter is not a constant expression
// error: 'non-constant initializer' : not supported with this profile: es
float f(const float p) {
    const float x = p;
    return x * p;
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(f(1.0));
}
