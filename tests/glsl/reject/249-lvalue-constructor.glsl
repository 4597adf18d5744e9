// rule: 5.8 Assignments: a constructor result is not an l-value
// error: 'assign' : l-value required (can't modify a const)
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 v;
    vec2(1.0) = vec2(2.0);
    fragColor = vec4(1.0);
}
