// rule: 4.1.9 Arrays: an array size must be greater than zero
// error: '' : array size must be a positive integer
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float a[-1];
    a[0] = 1.0;
    fragColor = vec4(a[0]);
}
