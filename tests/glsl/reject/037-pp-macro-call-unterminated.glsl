// rule: 3.3 Preprocessor: a macro invocation's argument list must be closed (here it runs into the text after the program)
// error: 'macro expansion' : unexpected '#' SQ
#define SQ(x) ((x) * (x))
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
const float K = SQ(2.0
