// rule: 3.3 Preprocessor: a macro name is an identifier, not a number
// error: '#define' : must be followed by macro name
#define 1 1.0
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
