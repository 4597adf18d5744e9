// rule: 4.1.10 Implicit Conversions: there are no implicit conversions; an array constructor's arguments must have the element type
// error: 'constructor' : cannot convert parameter 2 from ' const int' to ' const float'
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float a[2] = float[2](1.0, 2);
    fragColor = vec4(a[0]);
}
