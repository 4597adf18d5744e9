// rule: 5.5 Vector Components: a vec3 has no a
// error: 'a' : vector swizzle selection out of range
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec3 c = vec3(1.0);
    fragColor = vec4(c, c.a);
}
