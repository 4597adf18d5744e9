// rule: 5.1 Operators: the condition of ?: is a scalar bool
// error: '' : boolean expression expected
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    int a = iFrame;
    float f = a ? 1.0 : 0.0;
    fragColor = vec4(f);
}
