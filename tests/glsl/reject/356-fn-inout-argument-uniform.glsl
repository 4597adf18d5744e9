// rule: 6.1.1 Function Calling Conventions: an inout argument must be writable (a uniform is not)
// error: 'assign' : l-value required "iTime" (can't modify a uniform)
void bump(inout float x) { x += 1.0; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float t = iTime;
    bump(iTime);
    fragColor = vec4(t);
}
