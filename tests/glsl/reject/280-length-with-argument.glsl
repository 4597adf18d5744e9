// rule: 5.7 Structure and Array Operations: length() takes no arguments
// error: 'length' : method does not accept any arguments
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float a[5];
    int n = a.length(1);
    fragColor = vec4(float(n));
}
