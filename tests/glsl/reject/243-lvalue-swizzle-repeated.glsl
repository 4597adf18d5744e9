// rule: 5.5 Vector Components: a swizzle with a repeated component is not an l-value
// error: 'assign' : l-value of swizzle cannot have duplicate components
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec4 v = vec4(1.0);
    v.xx = vec2(2.0);
    fragColor = v;
}
