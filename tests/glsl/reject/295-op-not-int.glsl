// rule: 5.1 Operators: ! takes a bool operand
// error: '!' : wrong operand type no operation '!' exists that takes an operand of type temp highp int (or there is ...
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    int a = iFrame;
    bool b = !a;
    fragColor = vec4(b ? 1.0 : 0.0);
}
