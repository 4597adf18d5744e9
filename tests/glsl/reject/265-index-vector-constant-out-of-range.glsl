// rule: 5.5 Vector Components: a constant index must be in range (vec4 index 4)
// error: '[' : vector index out of range '4'
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec4 v = vec4(1.0);
    fragColor = vec4(v[4]);
}
