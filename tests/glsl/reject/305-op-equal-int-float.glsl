// rule: 5.1 Operators: == needs operands of the same type (int and float)
// error: '==' : wrong operand types: no operation '==' exists that takes a left-hand operand of type ' uniform highp...
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    bool b = iFrame == 0.0;
    fragColor = vec4(b ? 1.0 : 0.0);
}
