// rule: 5.4.2 Vector and Matrix Constructors: a matrix built from a matrix takes only that argument
// error: 'constructor' : matrix constructed from matrix can only have one argument
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    mat3 m = mat3(mat2(1.0), 1.0);
    fragColor = vec4(m[0], 1.0);
}
