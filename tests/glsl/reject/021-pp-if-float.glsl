// rule: 3.3 Preprocessor: #if expressions are integer expressions; a float literal is not allowed
// error: 'preprocessor evaluation' : bad expression
#if 1.0
#define A 1.0
#endif
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(A);
}
