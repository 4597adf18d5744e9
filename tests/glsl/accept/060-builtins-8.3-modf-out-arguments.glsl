// exercises: 8.3 modf on every genType, the out argument being a variable, an array element, a struct member and a swizzle
struct Parts { vec3 whole; };
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 p = fragCoord / iResolution.xy * 7.3;
    float w1;
    float f1 = modf(p.x, w1);
    vec2 w2[2];
    vec2 f2 = modf(p, w2[1]);
    Parts parts;
    vec3 f3 = modf(vec3(p, p.x + p.y), parts.whole);
    vec4 w4 = vec4(0.0);
    vec4 f4 = modf(vec4(p, p), w4);
    vec4 wz = vec4(0.0);
    vec2 f5 = modf(p.yx, wz.zx);
    fragColor = vec4(f1 + w1, f2 + w2[1], f3.x + parts.whole.y + f4.w + w4.z + f5.x + wz.z);
}
