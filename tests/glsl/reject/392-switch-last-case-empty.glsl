// rule: 6.2 Selection: the last case of a switch must be followed by a statement
// error: 'switch' : last case/default label not followed by statements
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(0.0);
    switch (iFrame) {
        case 1: fragColor = vec4(1.0); break;
        case 2:
    }
}
