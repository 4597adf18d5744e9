// rule: 3.3 Preprocessor: `defined` produced by macro expansion in #if (undefined in C++; WebGL 2 requires an error)
// error: 'defined' : cannot use in preprocessor expression when expanded from macros
#define HAS_A defined(A)
#if HAS_A
#define B 1.0
#else
#define B 2.0
#endif
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(B);
}
