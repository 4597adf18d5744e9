// rule: 8.3 Common Functions: abs has float and int overloads, not uint
// error: 'abs' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    uint a = abs(1u);
    fragColor = vec4(float(a));
}
