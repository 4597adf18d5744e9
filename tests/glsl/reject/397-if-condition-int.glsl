// rule: 6.2 Selection: an if condition is a scalar bool
// error: '' : boolean expression expected
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(0.0);
    if (iFrame) fragColor = vec4(1.0);
}
