// rule: 8 Built-in Functions: fma is not an ES 3.00 built-in
// error: 'fma' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(fma(1.0, 2.0, 3.0));
}
