// rule: 5.1 Operators: int and uint do not mix in comparisons
// error: '<' : wrong operand types: no operation '<' exists that takes a left-hand operand of type ' temp highp int'...
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    int a = 1;
    uint b = 2u;
    bool c = a < b;
    fragColor = vec4(c ? 1.0 : 0.0);
}
