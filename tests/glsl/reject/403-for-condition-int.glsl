// rule: 6.3 Iteration: a loop condition is a scalar bool
// error: '' : boolean expression expected
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float s = 0.0;
    for (int i = 3; i; i--) s += 1.0;
    fragColor = vec4(s);
}
