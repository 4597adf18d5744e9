// rule: 5.1 Operators: ^^ takes scalar bool operands, not bvec
// error: '^^' : wrong operand types: no operation '^^' exists that takes a left-hand operand of type ' temp 2-compon...
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    bvec2 a = bvec2(true, false);
    bool b = a ^^ a;
    fragColor = vec4(b ? 1.0 : 0.0);
}
