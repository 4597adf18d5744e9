// rule: 4.1.3 Integers: 0x must be followed by hexadecimal digits
// error: '' : bad digit in hexadecimal literal
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    int i = 0x;
    fragColor = vec4(float(i));
}
