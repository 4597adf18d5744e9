// rule: 3.3 Preprocessor: the preprocessor has no ?: operator
// error: '#if' : unexpected tokens following directive
#if 1 ? 1 : 0
#define A 1.0
#endif
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(A);
}
