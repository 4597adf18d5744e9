// rule: 5.7 Structure and Array Operations: an index is an integer expression
// error: '[]' : scalar integer expression required
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float a[3];
    a[1.0] = 1.0;
    fragColor = vec4(a[1]);
}
