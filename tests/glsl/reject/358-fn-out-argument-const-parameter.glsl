// rule: 6.1.1 Function Calling Conventions: a const parameter cannot be passed as an out argument
// error: 'assign' : l-value required "y" (can't modify a const)
void set(out float x) { x = 1.0; }
float g(const float y) { set(y); return y; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(g(0.0));
}
