// rule: 6.4 Jumps: a non-void function must return a value
// error: 'return' : non-void function must return a value
float f(float x) {
    if (x > 1.0) return;
    return 0.0;
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(f(1.0));
}
