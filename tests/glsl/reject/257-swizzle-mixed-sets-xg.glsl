// rule: 5.5 Vector Components: a swizzle uses letters of one set only (x and g mixed)
// error: 'xg' : vector swizzle selectors not from the same set
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec4 v = vec4(1.0);
    fragColor = vec4(v.xg, 0.0, 1.0);
}
