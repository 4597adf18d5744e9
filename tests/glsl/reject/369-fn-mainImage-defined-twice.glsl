// rule: 6.1 Function Definitions: a function can have only one body
// error: 'mainImage' : function already has a body
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(0.0);
}
