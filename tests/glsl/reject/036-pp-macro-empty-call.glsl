// rule: 3.3 Preprocessor: a function-like macro is invoked with as many arguments as it has parameters (glslang counts `F()` as none)
// error: 'macro expansion' : Too few args in Macro SQ
#define SQ(x) ((x) * (x))
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0 + SQ());
}
