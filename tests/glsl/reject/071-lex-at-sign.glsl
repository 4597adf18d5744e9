// rule: 3.1 Character Set: `@` is not in the character set
// error: '@' : unexpected token
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float x = 1.0 @ 2.0;
    fragColor = vec4(x);
}
