// rule: 8.3 Common Functions: min(int, float) has no overload (no conversion)
// error: 'min' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(min(1, iTime));
}
