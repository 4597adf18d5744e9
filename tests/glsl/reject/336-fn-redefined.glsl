// rule: 6.1 Function Definitions: a function can have only one body
// error: 'f' : function already has a body
float f(float a) { return a; }
float f(float b) { return 2.0 * b; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(f(1.0));
}
