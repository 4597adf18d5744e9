// rule: 5.1 Operators: ++ does not apply to structs
// error: '++' : wrong operand type no operation '++' exists that takes an operand of type temp structure{ global hig...
struct S { float a; };
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    S s = S(1.0);
    s++;
    fragColor = vec4(s.a);
}
