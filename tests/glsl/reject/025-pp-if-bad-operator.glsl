// rule: 3.3 Preprocessor: a #if expression must be well formed (++ is not a preprocessor operator)
// error: 'preprocessor evaluation' : bad expression
#if ++1
#define A 1.0
#endif
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(A);
}
