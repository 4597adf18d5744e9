// rule: 4.3.3 Constant Expressions: a loop index is not a constant expression
// error: 'non-constant initializer' : not supported with this profile: es
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float s = 0.0;
    for (int i = 0; i < 3; i++) {
        const int j = i;
        s += float(j);
    }
    fragColor = vec4(s);
}
