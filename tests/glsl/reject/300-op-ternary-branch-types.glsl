// rule: 5.1 Operators: both branches of ?: have the same type
// error: ':' : wrong operand types: no operation ':' exists that takes a left-hand operand of type ' const float' an...
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 f = iTime > 1.0 ? 1.0 : vec2(0.0);
    fragColor = vec4(f, 0.0, 1.0);
}
