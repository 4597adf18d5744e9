// rule: 6.2 Selection: the switch expression is a scalar integer
// error: 'switch' : condition must be a scalar integer expression
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    switch (iTime > 1.0) {
        case 1: fragColor = vec4(1.0); break;
        default: fragColor = vec4(0.0);
    }
}
