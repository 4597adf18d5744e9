// rule: 8.3 Common Functions: step takes two arguments
// error: 'step' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(step(iTime));
}
