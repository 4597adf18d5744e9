// rule: 5.7 Structure and Array Operations: a constant index cannot be negative
// error: '[' : index out of range '-1'
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float a[3];
    a[-1] = 1.0;
    fragColor = vec4(a[0]);
}
