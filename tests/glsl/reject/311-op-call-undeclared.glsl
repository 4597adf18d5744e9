// rule: 5.3 Function Calls: the called function must be declared
// error: 'hash12' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float y = hash12(2.0);
    fragColor = vec4(y);
}
