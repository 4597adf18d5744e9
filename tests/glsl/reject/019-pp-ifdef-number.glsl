// rule: 3.3 Preprocessor: #ifdef needs an identifier, not a number
// error: '#ifdef' : must be followed by macro name
#ifdef 1
#define A 1.0
#endif
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(A);
}
