// rule: 4.1.9 Arrays: a const parameter is not a constant expression, so it cannot size an array
// error: '' : array size must be a constant integer expression
float f(const int n) {
    float a[n];
    a[0] = float(n);
    return a[0];
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(f(2));
}
