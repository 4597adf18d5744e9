// rule: 8.3 Common Functions: mix takes three arguments
// error: 'mix' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(mix(0.0, 1.0));
}
