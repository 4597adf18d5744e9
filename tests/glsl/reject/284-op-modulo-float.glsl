// rule: 5.1 Operators: % is defined on integer types only; floats use mod()
// error: '%' : wrong operand types: no operation '%' exists that takes a left-hand operand of type ' temp highp floa...
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float a = 5.0;
    float b = a % 2.0;
    fragColor = vec4(b);
}
