// rule: 5.1 Operators: the condition of ?: is a scalar bool, not a bvec
// error: '' : boolean expression expected
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    bvec2 a = bvec2(true, false);
    float f = a ? 1.0 : 0.0;
    fragColor = vec4(f);
}
