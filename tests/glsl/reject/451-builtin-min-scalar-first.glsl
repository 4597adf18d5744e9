// rule: 8.3 Common Functions: only the second argument may be a scalar (min(vec, float))
// error: 'min' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 m = min(1.0, fragCoord);
    fragColor = vec4(m, 0.0, 1.0);
}
