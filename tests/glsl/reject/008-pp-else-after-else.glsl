// rule: 3.3 Preprocessor: a group has at most one #else
// error: '#else' : #else after #else
#if 1
#define A 1.0
#else
#define A 2.0
#else
#endif
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(A);
}
