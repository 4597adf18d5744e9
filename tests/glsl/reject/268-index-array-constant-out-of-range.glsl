// rule: 5.7 Structure and Array Operations: a constant array index must be in range
// error: '[' : array index out of range '3'
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float a[3];
    a[3] = 1.0;
    fragColor = vec4(a[2]);
}
