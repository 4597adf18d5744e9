// rule: 6.1 Function Definitions: parameter names must be distinct
// error: 'a' : redefinition
float add(float a, float a) { return a + a; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(add(1.0, 2.0));
}
