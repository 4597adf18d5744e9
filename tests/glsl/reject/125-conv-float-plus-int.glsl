// rule: 4.1.10 Implicit Conversions: there are no implicit conversions; float + int has no operator
// error: '+' : wrong operand types: no operation '+' exists that takes a left-hand operand of type ' uniform highp f...
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float x = iTime + iFrame;
    fragColor = vec4(x);
}
