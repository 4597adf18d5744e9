// rule: 6.2 Selection: case labels cannot be nested inside a block of the switch body
// error: 'case' : cannot be nested inside control flow
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(0.0);
    switch (iFrame) {
        case 1: { case 2: fragColor = vec4(1.0); } break;
        default: break;
    }
}
