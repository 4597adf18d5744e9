// rule: 4.1.8 Structures: a struct needs at least one member
// error: '' : syntax error, unexpected RIGHT_BRACE
struct Empty { };
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
