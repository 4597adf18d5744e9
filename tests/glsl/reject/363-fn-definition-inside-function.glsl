// rule: 6.1 Function Definitions: functions are defined at global scope only
// error: '' : syntax error, unexpected LEFT_BRACE, expecting SEMICOLON
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float helper() { return 1.0; }
    fragColor = vec4(helper());
}
