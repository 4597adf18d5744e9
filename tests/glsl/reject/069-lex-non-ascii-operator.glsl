// rule: 3.1 Character Set: outside comments only the listed ASCII characters may be used (× is not *)
// error: '�' : unexpected token
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float a = 2.0 × 3.0;
    fragColor = vec4(a);
}
