// rule: 5.10 Vector and Matrix Operations: ivec2 + vec2 has no operator
// error: '+' : wrong operand types: no operation '+' exists that takes a left-hand operand of type ' const 2-compone...
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 v = ivec2(1) + vec2(1.0);
    fragColor = vec4(v, 0.0, 1.0);
}
