// rule: 8 Built-in Functions: bitCount is not an ES 3.00 built-in
// error: 'bitCount' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(float(bitCount(5)));
}
