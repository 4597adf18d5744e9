// rule: 3.3 Preprocessor: #ifdef takes exactly one macro name
// error: '#ifdef' : unexpected tokens following #ifdef directive - expected a newline
#ifdef GL_ES __VERSION__
#define A 1.0
#endif
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(A);
}
