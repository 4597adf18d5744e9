// rule: 4.3.2 Constant Qualifier: a const variable cannot be written, also from a function
// error: 'assign' : l-value required (can't modify a const)
const float scale = 1.0;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    scale = 2.0;
    fragColor = vec4(scale);
}
