// rule: 5.1 Operators: < > <= >= take scalars; vectors use lessThan() etc.
// error: '<' : wrong operand types: no operation '<' exists that takes a left-hand operand of type ' temp highp 2-co...
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 a = vec2(1.0);
    bool b = a < vec2(2.0);
    fragColor = vec4(b ? 1.0 : 0.0);
}
