// rule: 6.2 Selection: case/default labels cannot be inside other control flow in the switch
// error: 'default' : cannot be nested inside control flow
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(0.0);
    switch (iFrame) {
        case 1: if (iTime > 1.0) { default: fragColor = vec4(1.0); } break;
    }
}
