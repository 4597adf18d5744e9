// rule: 3.3 Preprocessor: #elif cannot follow #else
// error: '#elif' : #elif after #else
#if 1
#define A 1.0
#else
#define B 2.0
#elif 0
#endif
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(A);
}
