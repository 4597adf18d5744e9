// rule: 5.3 Function Calls: an array argument must have the parameter's size
// error: 'first' : no matching overloaded function found
float first(float a[3]) { return a[0]; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float b[2];
    b[0] = 1.0;
    fragColor = vec4(first(b));
}
