// rule: 6.4 Jumps: continue is allowed only in loops
// error: '' : continue statement only allowed in loops
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
    if (iTime > 10.0) continue;
}
