// rule: 8.2 Exponential Functions: pow takes floats
// error: 'pow' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(pow(2, 3));
}
