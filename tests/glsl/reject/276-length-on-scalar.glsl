// rule: 5.7 Structure and Array Operations: .length() applies to arrays
// error: 'length' : does not operate on this type: temp highp float
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float f = 1.0;
    int n = f.length();
    fragColor = vec4(float(n));
}
