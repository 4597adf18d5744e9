// rule: 8.9 Fragment Processing Functions: dFdxFine is not in ES 3.00
// error: 'dFdxFine' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(dFdxFine(fragCoord.x));
}
