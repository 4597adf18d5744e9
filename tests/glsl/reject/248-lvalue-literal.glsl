// rule: 5.8 Assignments: a literal is not an l-value
// error: 'assign' : l-value required (can't modify a const)
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float a;
    1.0 = 2.0;
    fragColor = vec4(1.0);
}
