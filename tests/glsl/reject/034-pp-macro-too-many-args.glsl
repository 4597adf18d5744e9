// rule: 3.3 Preprocessor: a function-like macro is invoked with as many arguments as it has parameters
// error: 'macro expansion' : Too many args in macro SQ
#define SQ(x) ((x) * (x))
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(SQ(2.0, 3.0));
}
