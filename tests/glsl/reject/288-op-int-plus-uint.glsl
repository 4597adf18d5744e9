// rule: 5.1 Operators: int and uint do not mix (no implicit conversion)
// error: '+' : wrong operand types: no operation '+' exists that takes a left-hand operand of type ' temp highp int'...
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    int a = 1;
    uint b = 2u;
    uint c = a + b;
    fragColor = vec4(float(c));
}
