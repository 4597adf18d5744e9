// rule: 5.4.4 Array Constructors: arguments must have the element type
// error: 'constructor' : cannot convert parameter 2 from ' const 2-component vector of float' to ' const float'
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float a[2] = float[2](1.0, vec2(2.0));
    fragColor = vec4(a[0]);
}
