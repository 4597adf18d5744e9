// rule: 6.4 Jumps: break is allowed only in loops and switch
// error: '' : break statement only allowed in switch and loops
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
    if (iTime > 10.0) break;
}
