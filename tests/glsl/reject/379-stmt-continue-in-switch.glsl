// rule: 6.4 Jumps: continue is allowed only in loops, not in a switch alone
// error: '' : continue statement only allowed in loops
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(0.0);
    switch (iFrame) {
        case 0: fragColor = vec4(1.0); continue;
        default: break;
    }
}
