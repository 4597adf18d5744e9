// rule: 3.3 Preprocessor: #define needs a macro name
// error: '#define' : must be followed by macro name
#define
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
