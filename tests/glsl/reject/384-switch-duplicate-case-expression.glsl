// rule: 6.2 Selection: case values must be distinct (1+1 equals 2)
// error: 'case' : duplicated value
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    switch (iFrame) {
        case 2: fragColor = vec4(1.0); break;
        case 1 + 1: fragColor = vec4(0.5); break;
        default: fragColor = vec4(0.0);
    }
}
