// rule: 5.10 Vector and Matrix Operations: vec3 + vec2 has no operator
// error: '+' : wrong operand types: no operation '+' exists that takes a left-hand operand of type ' const 3-compone...
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec3 v = vec3(1.0) + vec2(1.0);
    fragColor = vec4(v, 1.0);
}
