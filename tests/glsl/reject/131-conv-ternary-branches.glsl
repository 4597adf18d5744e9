// rule: 4.1.10 Implicit Conversions: there are no implicit conversions; ?: branches float and int do not match
// error: ':' : wrong operand types: no operation ':' exists that takes a left-hand operand of type ' const float' an...
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float x = iTime > 1.0 ? 1.0 : 0;
    fragColor = vec4(x);
}
