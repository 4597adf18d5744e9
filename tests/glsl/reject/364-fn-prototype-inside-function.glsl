// rule: 6.1 Function Definitions: functions are declared at global scope only (no local prototypes)
// error: 'local function declaration' : not supported with this profile: es
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float helper();
    fragColor = vec4(helper());
}
float helper() { return 1.0; }
