// rule: 5.3 Function Calls: no overload takes an int
// error: 'f' : no matching overloaded function found
float f(float a) { return a; }
float f(vec2 a) { return a.x; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(f(1));
}
