// rule: 4.1.9 Arrays: an array size must be an integral expression
// error: '' : array size must be a constant integer expression
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float a[2.0];
    a[0] = 1.0;
    fragColor = vec4(a[0]);
}
