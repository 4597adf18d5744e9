// rule: 5.8 Assignments: ++x is not an l-value in GLSL
// error: 'assign' : l-value required
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float a = 1.0;
    ++a = 3.0;
    fragColor = vec4(a);
}
