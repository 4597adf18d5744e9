// rule: 4.1.8 Structures: each member declaration ends with ;
// error: '' : syntax error, unexpected RIGHT_BRACE, expecting COMMA or SEMICOLON
struct S { float a };
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
