// rule: 3.6 Keywords: keywords cannot name functions
// error: '' : syntax error, unexpected SWITCH, expecting COMMA or SEMICOLON
float switch(float x) { return x; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(switch(1.0));
}
