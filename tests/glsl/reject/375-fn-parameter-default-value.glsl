// rule: 6.1 Function Definitions: parameters have no default values
// error: '' : syntax error, unexpected EQUAL, expecting RIGHT_PAREN
float f(float x = 1.0) { return x; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(f(1.0));
}
