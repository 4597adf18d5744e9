// rule: 5.3 Function Calls: a void function's result has no value
// error: '=' : cannot convert from ' global void' to ' temp highp float'
void nothing() { }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float x = nothing();
    fragColor = vec4(x);
}
