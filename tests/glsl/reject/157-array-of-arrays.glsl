// rule: 4.1.9 Arrays: ES 3.00 has only one-dimensional arrays
// error: 'arrays of arrays' : not supported for this version or the enabled extensions
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float a[2][3];
    a[0][0] = 1.0;
    fragColor = vec4(1.0);
}
