// rule: 6.1 Function Definitions: overloads cannot differ only in return type
// error: 'f' : overloaded functions must have the same return type
float f(float a) { return a; }
int f(float a) { return 1; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(f(1.0));
}
