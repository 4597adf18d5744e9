// rule: 6.1 Function Definitions: built-in functions cannot be redefined in ES 3.00
// error: 'redefinition of built-in function' : not supported with this profile: es
float sin(float x) { return x; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(sin(1.0));
}
