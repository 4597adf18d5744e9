// rule: 3.3 Preprocessor: #if needs an expression
// error: 'preprocessor evaluation' : bad expression
#if
#define A 1.0
#endif
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(A);
}
