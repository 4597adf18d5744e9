// rule: 8 Built-in Functions: bitfieldExtract is not an ES 3.00 built-in
// error: 'bitfieldExtract' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(float(bitfieldExtract(5, 0, 2)));
}
