// rule: 3.3 Preprocessor: `defined(` needs its closing parenthesis
// error: 'preprocessor evaluation' : expected ')'
#if defined(GL_ES
#define A 1.0
#endif
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(A);
}
