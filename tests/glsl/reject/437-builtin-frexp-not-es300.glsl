// rule: 8 Built-in Functions: frexp is not an ES 3.00 built-in
// error: 'frexp' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    int e;
    fragColor = vec4(frexp(8.0, e));
}
