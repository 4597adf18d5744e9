// rule: 6.1 Function Definitions: the epilogue calls mainImage(vec4, vec2); it must exist
// error: 'mainImage' : no matching overloaded function found
void mainimage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
