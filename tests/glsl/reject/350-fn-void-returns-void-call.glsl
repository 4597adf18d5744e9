// rule: 6.4 Jumps: a void function cannot return an expression, not even a void one
// error: 'return' : void function cannot return a value
void clear(out vec4 c) { c = vec4(0.0); }
void paint(out vec4 c) {
    return clear(c);
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    paint(fragColor);
}
