// rule: 6.2 Selection: a case label is a constant integral expression
// error: 'case' : constant expression required
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    int k = 1;
    switch (iFrame) {
        case k: fragColor = vec4(1.0); break;
        default: fragColor = vec4(0.0);
    }
}
