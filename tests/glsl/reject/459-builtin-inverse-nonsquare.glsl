// rule: 8.6 Matrix Functions: inverse takes a square matrix
// error: 'inverse' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    mat3 m = inverse(mat2x3(1.0))[0][0] * mat3(1.0);
    fragColor = vec4(m[0], 1.0);
}
