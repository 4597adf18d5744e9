// rule: 6.3 Iteration: a condition declaration must be of type bool
// error: '' : boolean expression expected
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    int i = 3;
    while (int b = i) { i--; }
    fragColor = vec4(1.0);
}
