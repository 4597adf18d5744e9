// rule: 3.3 Preprocessor: nothing may follow #endif on its line (C++ rules)
// error: '#endif' : unexpected tokens following directive
#ifdef GL_ES
#define A 1.0
#endif GL_ES
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(A);
}
