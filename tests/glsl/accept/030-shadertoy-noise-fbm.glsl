// exercises: a typical ShaderToy program: integer hashing with uint arithmetic, value noise, fbm with a rotation matrix, a cosine palette, domain warping
uint hash(uint x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}
float hash21(vec2 p) {
    uvec2 q = uvec2(ivec2(floor(p)) + 32768);
    return float(hash(q.x + hash(q.y))) / 4294967295.0;
}
float noise(vec2 p) {
    vec2 i = floor(p), f = fract(p);
    vec2 u = f * f * (3.0 - 2.0 * f);
    return mix(mix(hash21(i), hash21(i + vec2(1.0, 0.0)), u.x), mix(hash21(i + vec2(0.0, 1.0)), hash21(i + 1.0), u.x), u.y);
}
const mat2 M = mat2(0.8, 0.6, -0.6, 0.8);
float fbm(vec2 p) {
    float v = 0.0, a = 0.5;
    for (int i = 0; i < 6; i++) {
        v += a * noise(p);
        p = M * p * 2.02;
        a *= 0.5;
    }
    return v;
}
vec3 palette(float t) {
    return 0.5 + 0.5 * cos(6.28318 * (vec3(1.0) * t + vec3(0.0, 0.33, 0.67)));
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 p = fragCoord / iResolution.y * 3.0;
    vec2 q = vec2(fbm(p + iTime * 0.1), fbm(p + vec2(5.2, 1.3)));
    float f = fbm(p + 4.0 * q);
    fragColor = vec4(palette(f + 0.2 * iTime), 1.0);
}
