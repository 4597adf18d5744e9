// rule: 3.3 Preprocessor: #ifdef needs a macro name
// error: '#ifdef' : must be followed by macro name
#ifdef
#define A 1.0
#endif
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(A);
}
