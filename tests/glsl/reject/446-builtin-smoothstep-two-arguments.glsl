// rule: 8.3 Common Functions: smoothstep takes three arguments
// error: 'smoothstep' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(smoothstep(0.0, iTime));
}
