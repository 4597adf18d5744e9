// rule: 6.1 Function Definitions: array parameters must be sized
// error: '' : array size required
float first(float a[]) { return a[0]; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(first(float[2](1.0, 2.0)));
}
