// rule: 8.9 Fragment Processing Functions: dFdx takes genType (float), not int
// error: 'dFdx' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    int i = iFrame;
    fragColor = vec4(dFdx(i));
}
