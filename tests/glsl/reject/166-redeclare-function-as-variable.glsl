// rule: 4.2 Scoping: a global variable cannot have the name of a function
// error: 'shade' : redefinition
float shade() { return 1.0; }
float shade = 2.0;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(shade());
}
