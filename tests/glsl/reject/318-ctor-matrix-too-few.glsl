// rule: 5.4.2 Vector and Matrix Constructors: a matrix built from components needs all of them
// error: 'constructor' : not enough data provided for construction
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    mat2 m = mat2(1.0, 2.0, 3.0);
    fragColor = vec4(m[0], m[1]);
}
