// rule: 6.3 Iteration: a loop condition is a scalar bool
// error: '' : boolean expression expected
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    int i = 3;
    while (i) { i--; }
    fragColor = vec4(1.0);
}
