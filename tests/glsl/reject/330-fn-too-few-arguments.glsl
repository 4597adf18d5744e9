// rule: 5.3 Function Calls: a call must match a declared overload (argument count)
// error: 'add' : no matching overloaded function found
float add(float a, float b) { return a + b; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(add(1.0));
}
