// rule: 5.5 Vector Components: component names are xyzw, rgba or stpq
// error: 'xk' : unknown swizzle selection
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec4 v = vec4(1.0);
    fragColor = vec4(v.xk, 0.0, 1.0);
}
