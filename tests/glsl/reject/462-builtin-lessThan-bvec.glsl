// rule: 8.7 Vector Relational Functions: lessThan does not take bvec
// error: 'lessThan' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    bvec2 b = lessThan(bvec2(true), bvec2(false));
    fragColor = vec4(b.x ? 1.0 : 0.0);
}
