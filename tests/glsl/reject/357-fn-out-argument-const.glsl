// rule: 6.1.1 Function Calling Conventions: an out argument must be writable (a const is not)
// error: 'assign' : l-value required (can't modify a const)
void set(out float x) { x = 1.0; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    const float c = 0.0;
    set(c);
    fragColor = vec4(c);
}
