// rule: 5.4.4 Array Constructors: one argument per element
// error: 'constructor' : array constructor needs one argument per array element
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float a[2] = float[2](1.0, 2.0, 3.0);
    fragColor = vec4(a[0]);
}
