// rule: 3.3 Preprocessor: an undefined identifier in #if is an error in ES (it is not 0 as in C)
// error: 'preprocessor evaluation' : undefined macro in expression not allowed in es profile QUALITY
#if QUALITY
#define A 2.0
#else
#define A 1.0
#endif
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(A);
}
