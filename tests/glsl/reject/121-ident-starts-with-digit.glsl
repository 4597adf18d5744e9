// rule: 3.7 Identifiers: an identifier cannot start with a digit
// error: '' : syntax error, unexpected INTCONSTANT, expecting COMMA or SEMICOLON
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float 2x = 1.0;
    fragColor = vec4(1.0);
}
