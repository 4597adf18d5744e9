// rule: 6.3 Iteration: the body of a while loop does not open a new scope over the condition declaration
// error: 'go' : redefinition
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    int k = 0;
    while (bool go = k < 2) {
        bool go = true;
        k++;
    }
    fragColor = vec4(1.0);
}
