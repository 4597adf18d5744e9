// rule: 5.1 Operators: unary - takes a numeric operand
// error: '-' : wrong operand type no operation '-' exists that takes an operand of type const bool (or there is no a...
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    bool b = -true;
    fragColor = vec4(b ? 1.0 : 0.0);
}
