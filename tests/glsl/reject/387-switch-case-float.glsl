// rule: 6.2 Selection: a case label is an integral expression
// error: 'case' : scalar integer expression required
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    switch (iFrame) {
        case 1.0: fragColor = vec4(1.0); break;
        default: fragColor = vec4(0.0);
    }
}
