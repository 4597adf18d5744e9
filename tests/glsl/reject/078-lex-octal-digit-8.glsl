// rule: 4.1.3 Integers: an octal literal (leading 0) has only digits 0-7
// error: '' : octal literal digit too large
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    int i = 08;
    fragColor = vec4(float(i));
}
