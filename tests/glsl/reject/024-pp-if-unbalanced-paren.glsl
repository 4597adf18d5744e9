// rule: 3.3 Preprocessor: a #if expression must be well formed (unclosed parenthesis)
// error: 'preprocessor evaluation' : expected ')'
#if (1 + 2 == 3
#define A 1.0
#endif
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(A);
}
