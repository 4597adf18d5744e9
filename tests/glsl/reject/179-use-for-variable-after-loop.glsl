// rule: 4.2 Scoping: a for-init variable is not visible after the loop
// error: 'i' : undeclared identifier
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    for (int i = 0; i < 3; i++) {}
    fragColor = vec4(float(i));
}
