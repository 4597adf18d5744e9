// rule: 4.1.4 Floats: u is an integer suffix; `1.0u` is not a literal
// error: '' : syntax error, unexpected IDENTIFIER, expecting COMMA or SEMICOLON
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float f = 1.0u;
    fragColor = vec4(f);
}
