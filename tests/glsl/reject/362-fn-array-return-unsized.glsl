// rule: 6.1 Function Definitions: an array return type must be sized
// error: '' : array size required
float[] weights() { return float[3](0.25, 0.5, 0.25); }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(weights()[1]);
}
