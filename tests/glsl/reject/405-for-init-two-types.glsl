// rule: 6.3 Iteration: the init statement is one declaration (one type)
// error: '' : syntax error, unexpected FLOAT, expecting IDENTIFIER
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float s = 0.0;
    for (int i = 0, float f = 0.0; i < 3; i++) s += 1.0;
    fragColor = vec4(s);
}
