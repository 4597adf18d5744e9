// rule: 8.3 Common Functions: clamp takes three arguments
// error: 'clamp' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(clamp(iTime, 0.0));
}
