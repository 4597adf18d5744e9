// rule: 5.6 Matrix Components: a matrix has no swizzle; its columns are m[i]
// error: 'x' : does not apply to this type: temp highp 2X2 matrix of float
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    mat2 m = mat2(1.0);
    fragColor = vec4(m.x, 0.0, 1.0);
}
