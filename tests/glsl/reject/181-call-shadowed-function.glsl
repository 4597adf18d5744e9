// rule: 4.2 Scoping: a local variable hides a function of the same name
// error: 'shade' : can't use function syntax on variable
float shade() { return 1.0; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float shade = 2.0;
    fragColor = vec4(shade() * shade);
}
