// rule: 5.5 Vector Components: a vec2 has no z
// error: 'z' : vector swizzle selection out of range
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 v = vec2(1.0);
    fragColor = vec4(v.z);
}
