// rule: 5.1 Operators: ^ is defined on integer types only
// error: '^' : wrong operand types: no operation '^' exists that takes a left-hand operand of type ' temp highp 2-co...
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 a = vec2(3.0);
    vec2 b = a ^ a;
    fragColor = vec4(b, b);
}
