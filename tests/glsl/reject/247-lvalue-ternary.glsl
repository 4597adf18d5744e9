// rule: 5.8 Assignments: a ?: expression is not an l-value
// error: 'assign' : l-value required
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float a = 1.0, b = 2.0;
    (iTime > 1.0 ? a : b) = 3.0;
    fragColor = vec4(a + b);
}
