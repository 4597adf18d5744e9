// rule: 3.3 Preprocessor: a function-like macro is invoked with as many arguments as it has parameters
// error: 'macro expansion' : Too few args in Macro ADD
#define ADD(a, b) ((a) + (b))
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(ADD(1.0));
}
