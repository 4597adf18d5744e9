// rule: 6.2 Selection: an if condition is a scalar bool, not a bvec
// error: '' : boolean expression expected
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(0.0);
    if (greaterThan(fragCoord, vec2(10.0))) fragColor = vec4(1.0);
}
