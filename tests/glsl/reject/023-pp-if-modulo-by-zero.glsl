// rule: 3.3 Preprocessor: modulo by zero in a #if expression is an error
// error: 'preprocessor evaluation' : division by 0
#if 5 % 0 == 1
#define A 1.0
#else
#define A 2.0
#endif
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(A);
}
