// rule: 5.1 Operators: ! takes a scalar bool; bvec uses not()
// error: '!' : wrong operand type no operation '!' exists that takes an operand of type temp 2-component vector of b...
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    bvec2 a = bvec2(true, false);
    bvec2 b = !a;
    fragColor = vec4(b.x ? 1.0 : 0.0);
}
