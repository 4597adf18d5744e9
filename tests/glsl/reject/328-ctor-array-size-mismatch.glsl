// rule: 5.8 Assignments: an array of 3 cannot initialise an array of 2
// error: '=' : cannot convert from ' const 3-element array of float' to ' temp 2-element array of highp float'
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float a[2] = float[3](1.0, 2.0, 3.0);
    fragColor = vec4(a[0]);
}
