// rule: 8.3 Common Functions: max takes two arguments
// error: 'max' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(max(1.0, 2.0, iTime));
}
