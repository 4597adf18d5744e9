// rule: 3.3 Preprocessor: after #undef the name is an ordinary (here undeclared) identifier
// error: 'X' : undeclared identifier
#define X 1.0
#undef X
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(X);
}
