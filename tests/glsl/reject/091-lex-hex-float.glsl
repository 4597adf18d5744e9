// rule: 4.1.4 Floats: there are no hexadecimal float literals (0x1p3 lexes as 0x1 then p3)
// error: '=' : cannot convert from ' const int' to ' temp highp float'
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float f = 0x1p3;
    fragColor = vec4(f);
}
