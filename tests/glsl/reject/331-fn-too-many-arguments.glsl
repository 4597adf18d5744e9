// rule: 5.3 Function Calls: a call must match a declared overload (argument count)
// error: 'twice' : no matching overloaded function found
float twice(float a) { return 2.0 * a; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(twice(1.0, 2.0));
}
