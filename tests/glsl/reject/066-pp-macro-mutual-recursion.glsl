// rule: 3.3 Preprocessor: a macro is not expanded inside its own expansion, so A stays an undeclared name
// error: 'A' : undeclared identifier
#define A (1.0 + B)
#define B (2.0 + A)
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(A);
}
