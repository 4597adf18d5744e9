// rule: 3.3 Preprocessor: #undef takes exactly one macro name
// error: '#undef' : can only be followed by a single macro name
#define A 1.0
#define B 2.0
#undef B A
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(A);
}
