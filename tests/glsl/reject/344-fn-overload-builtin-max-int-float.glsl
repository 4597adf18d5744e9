// rule: 6.1 Function Definitions: built-in functions cannot be overloaded in ES 3.00 (max(int, float))
// error: 'max' : function name is redeclaration of existing name
float max(int a, float b) { return float(a) > b ? float(a) : b; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(max(1, 2.0));
}
