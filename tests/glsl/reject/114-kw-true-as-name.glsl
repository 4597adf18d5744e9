// rule: 3.6 Keywords: true is a keyword (a boolean literal), not a name
// error: '' : syntax error, unexpected BOOLCONSTANT, expecting COMMA or SEMICOLON
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float true = 1.0;
    fragColor = vec4(1.0);
}
