// rule: 6.3 Iteration: the body of a for loop does not open a new scope over the init declaration
// error: 'i' : redefinition
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float s = 0.0;
    for (int i = 0; i < 3; i++) {
        int i = 2;
        s += 1.0;
    }
    fragColor = vec4(s);
}
