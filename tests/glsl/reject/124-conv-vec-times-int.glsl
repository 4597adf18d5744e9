// rule: 4.1.10 Implicit Conversions: there are no implicit conversions; vec2 * int has no operator
// error: '*' : wrong operand types: no operation '*' exists that takes a left-hand operand of type ' const 2-compone...
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 v = vec2(1.0) * 2;
    fragColor = vec4(v, 0.0, 1.0);
}
