// rule: 5.3 Function Calls: a call must match a declared overload exactly (vec3 for vec2)
// error: 'sum' : no matching overloaded function found
float sum(vec2 a) { return a.x + a.y; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(sum(vec3(1.0)));
}
