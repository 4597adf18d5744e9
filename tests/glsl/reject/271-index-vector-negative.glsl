// rule: 5.5 Vector Components: a constant index cannot be negative
// error: '[' : index out of range '-1'
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec3 v = vec3(1.0);
    fragColor = vec4(v[-1]);
}
