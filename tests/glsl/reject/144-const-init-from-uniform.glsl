// rule: 4.3.3 Constant Expressions: a const initialiser must be a constant expression; a uniform is not
// error: 'non-constant initializer' : not supported with this profile: es
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    const float t = iTime;
    fragColor = vec4(t);
}
