// rule: 5.1 Operators: ++ takes an integer or float operand
// error: '++' : wrong operand type no operation '++' exists that takes an operand of type temp bool (or there is no ...
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    bool b = true;
    b++;
    fragColor = vec4(1.0);
}
