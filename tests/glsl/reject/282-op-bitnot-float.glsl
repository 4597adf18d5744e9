// rule: 5.1 Operators: ~ is defined on integer types only
// error: '~' : wrong operand type no operation '~' exists that takes an operand of type temp highp float (or there i...
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float a = 3.0;
    float b = ~a;
    fragColor = vec4(b);
}
