// rule: 3.1 Character Set: outside comments only the listed ASCII characters may be used
// error: '�' : unexpected token
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float é = 1.0;
    fragColor = vec4(é);
}
