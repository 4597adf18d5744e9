// rule: 4.1.7 Sampler Types: samplers cannot be operands of ?:
// error: ':' : wrong operand types: no operation ':' exists that takes a left-hand operand of type ' uniform highp s...
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = texture(iTime > 1.0 ? iChannel0 : iChannel1, vec2(0.5));
}
