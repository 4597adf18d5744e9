// rule: 4.2 Scoping: a name is visible only after its declaration
// error: 'x' : undeclared identifier
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    x = 1.0;
    float x;
    fragColor = vec4(x);
}
