// rule: 8.7 Vector Relational Functions: lessThan takes two vectors of the same type
// error: 'lessThan' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    bvec2 b = lessThan(fragCoord, ivec2(1));
    fragColor = vec4(b.x ? 1.0 : 0.0);
}
