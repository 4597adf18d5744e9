// rule: 3.3 Preprocessor: `defined` must be followed by an identifier
// error: 'preprocessor evaluation' : incorrect directive, expected identifier
#if defined
#define A 1.0
#endif
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(A);
}
