// rule: 8.3 Common Functions: mod is float only; ints use %
// error: 'mod' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    int a = mod(iFrame, 2);
    fragColor = vec4(float(a));
}
