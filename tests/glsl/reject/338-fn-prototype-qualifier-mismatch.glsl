// rule: 6.1 Function Definitions: a prototype and its definition must have the same parameter qualifiers
// error: 'out' : overloaded functions must have the same parameter storage qualifiers for argument 1
float f(in float a);
float f(out float a) { a = 1.0; return a; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float x;
    fragColor = vec4(f(x));
}
