// rule: 6.4 Jumps: mainImage is void; it cannot return a value
// error: 'return' : void function cannot return a value
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
    return fragColor;
}
