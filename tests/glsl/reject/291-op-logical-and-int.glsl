// rule: 5.1 Operators: && takes bool operands
// error: '&&' : wrong operand types: no operation '&&' exists that takes a left-hand operand of type ' temp highp in...
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    int a = iFrame;
    bool b = a && iTime > 0.0;
    fragColor = vec4(b ? 1.0 : 0.0);
}
