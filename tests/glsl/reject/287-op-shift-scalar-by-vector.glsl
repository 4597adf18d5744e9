// rule: 5.1 Operators: a scalar cannot be shifted by a vector
// error: '<<' : wrong operand types: no operation '<<' exists that takes a left-hand operand of type ' temp highp in...
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    int a = 1;
    ivec2 b = a << ivec2(1, 2);
    fragColor = vec4(vec2(b), 0.0, 1.0);
}
