// rule: 5.1 Operators: ++ does not apply to arrays
// error: '++' : wrong operand type no operation '++' exists that takes an operand of type temp 2-element array of hi...
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float a[2];
    a[0] = 0.0;
    a++;
    fragColor = vec4(a[0]);
}
