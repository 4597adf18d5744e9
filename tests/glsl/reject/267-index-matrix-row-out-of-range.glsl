// rule: 5.6 Matrix Components: a constant row index must be in range
// error: '[' : vector index out of range '3'
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    mat3 m = mat3(1.0);
    fragColor = vec4(m[0][3]);
}
