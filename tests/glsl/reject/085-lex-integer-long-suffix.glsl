// rule: 4.1.3 Integers: the only integer suffix is u/U (no l, no 64-bit literals)
// error: '64-bit literal' : not supported with this profile: es
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    int i = 1l;
    fragColor = vec4(float(i));
}
