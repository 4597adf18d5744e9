// rule: 6.1.1 Function Calling Conventions: an out argument must be an l-value (an expression is not)
// error: 'assign' : l-value required
void set(out float x) { x = 1.0; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float a = 1.0;
    set(a + 1.0);
    fragColor = vec4(a);
}
