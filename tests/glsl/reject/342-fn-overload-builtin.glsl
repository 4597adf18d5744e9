// rule: 6.1 Function Definitions: built-in functions cannot be overloaded in ES 3.00
// error: 'sin' : function name is redeclaration of existing name
float sin(vec2 x, float k) { return k * x.x; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(sin(vec2(1.0), 2.0));
}
