// rule: 3.3 Preprocessor: `#` must be the first token of its line
// error: '#' : preprocessor directive cannot be preceded by another token
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0); #define A 1
}
