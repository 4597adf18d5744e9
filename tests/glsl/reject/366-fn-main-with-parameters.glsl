// rule: 6.1 Function Definitions: main takes no parameters (and cannot be overloaded)
// error: 'main' : function cannot take any parameter(s)
void main(int x) { }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
