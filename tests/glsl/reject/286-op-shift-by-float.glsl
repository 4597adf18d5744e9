// rule: 5.1 Operators: the shift amount is an integer
// error: '<<' : wrong operand types: no operation '<<' exists that takes a left-hand operand of type ' temp highp in...
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    int a = 1;
    int b = a << 1.0;
    fragColor = vec4(float(b));
}
