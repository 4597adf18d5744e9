// rule: 6.1 Function Definitions: a return type takes no storage qualifier
// error: 'const' : no qualifiers allowed for function return
const float one() { return 1.0; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(one());
}
