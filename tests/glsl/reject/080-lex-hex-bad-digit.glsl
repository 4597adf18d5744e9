// rule: 4.1.3 Integers: hexadecimal digits are 0-9, a-f, A-F
// error: '' : bad digit in hexadecimal literal
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    int i = 0xg1;
    fragColor = vec4(float(i));
}
