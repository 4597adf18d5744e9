// rule: 6.2 Selection: no statement may come before the first case label
// error: 'switch' : cannot have statements before first case/default label
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(0.0);
    switch (iFrame) {
        fragColor = vec4(0.5);
        case 1: fragColor = vec4(1.0); break;
    }
}
