// rule: 5.1 Operators: == needs operands of the same type (vec2 and vec3)
// error: '==' : wrong operand types: no operation '==' exists that takes a left-hand operand of type ' const 2-compo...
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    bool b = vec2(1.0) == vec3(1.0);
    fragColor = vec4(b ? 1.0 : 0.0);
}
