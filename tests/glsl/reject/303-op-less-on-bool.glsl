// rule: 5.1 Operators: < takes numeric scalars, not bool
// error: '<' : wrong operand types: no operation '<' exists that takes a left-hand operand of type ' const bool' and...
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    bool b = true < false;
    fragColor = vec4(b ? 1.0 : 0.0);
}
