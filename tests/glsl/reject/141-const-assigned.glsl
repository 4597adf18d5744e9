// rule: 4.3.2 Constant Qualifier: a const variable cannot be written
// error: 'assign' : l-value required (can't modify a const)
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    const float x = 1.0;
    x = 2.0;
    fragColor = vec4(x);
}
