// rule: 6.1 Function Definitions: the epilogue defines main(); a program cannot define it too
// error: 'main' : function already has a body
void main() { }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
