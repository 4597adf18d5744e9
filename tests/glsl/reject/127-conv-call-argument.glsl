// rule: 4.1.10 Implicit Conversions: there are no implicit conversions; f(1) does not match f(float)
// error: 'twice' : no matching overloaded function found
float twice(float x) { return 2.0 * x; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(twice(1));
}
