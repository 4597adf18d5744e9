// rule: 6.1 Function Definitions: a prototype and its definition must agree on const parameters
// error: 'in' : overloaded functions must have the same parameter storage qualifiers for argument 1
float f(const float a);
float f(float a) { return a; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(f(1.0));
}
