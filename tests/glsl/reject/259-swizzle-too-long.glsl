// rule: 5.5 Vector Components: a swizzle has at most 4 components
// error: 'xyzwx' : vector swizzle too long
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec4 v = vec4(1.0);
    fragColor = v.xyzwx;
}
