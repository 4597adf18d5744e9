// rule: 5.1 Operators: int and uint do not mix in bitwise operators
// error: '&' : wrong operand types: no operation '&' exists that takes a left-hand operand of type ' temp highp uint...
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    int a = 1;
    uint b = 6u;
    uint c = b & a;
    fragColor = vec4(float(c));
}
