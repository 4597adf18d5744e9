// rule: 4.1.10 Implicit Conversions: there are no implicit conversions; `return 1;` in a float function
// error: 'return' : type does not match, or is not convertible to, the function's return type
float one() { return 1; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(one());
}
