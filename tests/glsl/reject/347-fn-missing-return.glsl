// rule: 6.1 Function Definitions: a non-void function must return a value
// error: '' : function does not return a value: f
float f(float x) {
    x = 2.0 * x;
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(f(1.0));
}
