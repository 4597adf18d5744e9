// rule: 6.1.1 Function Calling Conventions: an out argument must be an l-value (a literal is not)
// error: 'assign' : l-value required (can't modify a const)
void set(out float x) { x = 1.0; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float v;
    set(1.0);
    fragColor = vec4(v);
}
