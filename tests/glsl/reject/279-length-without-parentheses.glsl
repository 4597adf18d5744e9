// rule: 5.7 Structure and Array Operations: length is a method: `a.length()`
// error: 'length' : incomplete method syntax
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float a[5];
    int n = a.length;
    fragColor = vec4(float(n));
}
