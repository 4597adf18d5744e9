// rule: 3.3 Preprocessor: the parameters of a function-like macro must have distinct names
// error: '#define' : duplicate macro parameter
#define ADD(a, a) ((a) + (b))
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(ADD(1.0, 2.0));
}
