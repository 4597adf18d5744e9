// rule: 4.1.10 Implicit Conversions: there are no implicit conversions; float > int has no operator
// error: '>' : wrong operand types: no operation '>' exists that takes a left-hand operand of type ' temp highp floa...
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float x = 0.5;
    if (x > 0) x = 1.0;
    fragColor = vec4(x);
}
