// rule: 6.4 Jumps: a void function cannot return a value
// error: 'return' : void function cannot return a value
void paint(out vec4 c) {
    c = vec4(1.0);
    return 1.0;
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    paint(fragColor);
}
