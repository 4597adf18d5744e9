// rule: 5.8 Assignments: a function call result is not an l-value
// error: 'assign' : l-value required
float level() { return 1.0; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float x;
    level() = 2.0;
    fragColor = vec4(1.0);
}
