// rule: 5.1 Operators: < takes scalars, not matrices
// error: '<' : wrong operand types: no operation '<' exists that takes a left-hand operand of type ' temp highp 2X2 ...
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    mat2 a = mat2(1.0);
    bool b = a < a;
    fragColor = vec4(b ? 1.0 : 0.0);
}
