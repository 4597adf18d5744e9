// rule: 6.2 Selection: the type of each case label must match the type of the switch expression (uint label, int switch)
// glslang: accepts: glslang converts the label; ANGLE rejects "case label type does not match switch init-expression type". rasterd rejects
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    switch (iFrame) {
        case 1u: fragColor = vec4(1.0); break;
        default: fragColor = vec4(0.0);
    }
}
