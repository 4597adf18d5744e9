// rule: 6 Statements and Structure: statements appear only inside functions
// error: '' : syntax error, unexpected IDENTIFIER
float g = 0.0;
g = 1.0;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(g);
}
