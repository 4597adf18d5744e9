// rule: 3.3 Preprocessor: nothing may follow #else on its line (C++ rules)
// error: '#else' : unexpected tokens following directive
#if 0
#define A 2.0
#else A
#define A 1.0
#endif
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(A);
}
