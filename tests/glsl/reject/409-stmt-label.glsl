// rule: 6 Statements and Structure: there are no labels
// error: 'done' : undeclared identifier
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    done: fragColor = vec4(1.0);
}
