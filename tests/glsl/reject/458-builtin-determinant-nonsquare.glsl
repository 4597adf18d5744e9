// rule: 8.6 Matrix Functions: determinant takes a square matrix
// error: 'determinant' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(determinant(mat2x3(1.0)));
}
