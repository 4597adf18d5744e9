// rule: 4.1.8 Structures: members cannot have initialisers
// error: '' : syntax error, unexpected EQUAL, expecting COMMA or SEMICOLON
struct S { float a = 1.0; };
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
