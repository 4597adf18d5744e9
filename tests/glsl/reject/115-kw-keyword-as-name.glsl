// rule: 3.6 Keywords: `smooth` is a keyword of ES 3.00 (interpolation qualifier), not a name
// error: '' : syntax error, unexpected SMOOTH, expecting COMMA or SEMICOLON
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float smooth = 1.0;
    fragColor = vec4(smooth);
}
