// rule: 5.6 Matrix Components: a constant column index must be in range
// error: '[' : matrix index out of range '3'
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    mat3 m = mat3(1.0);
    fragColor = vec4(m[3], 1.0);
}
