// rule: 4.3.9 Interpolation: interpolation qualifiers are for global inputs and outputs
// error: 'flat' : not allowed in nested scope
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    flat float x = 1.0;
    fragColor = vec4(x);
}
