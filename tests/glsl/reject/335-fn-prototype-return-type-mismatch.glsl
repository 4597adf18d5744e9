// rule: 6.1 Function Definitions: a prototype and its definition must have the same return type
// error: 'f' : overloaded functions must have the same return type
int f(float a);
float f(float a) { return a; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(f(1.0));
}
