// rule: 4.2 Scoping: a variable declared in a block is not visible after it
// error: 'x' : undeclared identifier
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    if (iTime > 0.0) {
        float x = 1.0;
    }
    fragColor = vec4(x);
}
