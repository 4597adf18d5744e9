// exercises: a typical ShaderToy program: a sphere-traced SDF scene with a camera matrix, normals by central differences, soft shadows, fog, gamma; helper functions, loops with break, const globals
const int MAX_STEPS = 100;
const float MAX_DIST = 50.0;
const float SURF_EPS = 0.001;
mat2 rot(float a) { float c = cos(a), s = sin(a); return mat2(c, -s, s, c); }
float sdSphere(vec3 p, float r) { return length(p) - r; }
float sdBox(vec3 p, vec3 b) { vec3 q = abs(p) - b; return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0); }
float smin(float a, float b, float k) { float h = clamp(0.5 + 0.5 * (b - a) / k, 0.0, 1.0); return mix(b, a, h) - k * h * (1.0 - h); }
float map(vec3 p) {
    vec3 q = p;
    q.xz *= rot(iTime * 0.5);
    float d = smin(sdSphere(q - vec3(0.0, 1.0, 0.0), 1.0), sdBox(q - vec3(1.2, 0.8, 0.0), vec3(0.5)), 0.3);
    return min(d, p.y);
}
vec3 calcNormal(vec3 p) {
    const vec2 e = vec2(1e-3, 0.0);
    return normalize(vec3(map(p + e.xyy) - map(p - e.xyy), map(p + e.yxy) - map(p - e.yxy), map(p + e.yyx) - map(p - e.yyx)));
}
float softShadow(vec3 ro, vec3 rd, float k) {
    float res = 1.0, t = 0.02;
    for (int i = 0; i < 32; i++) {
        float h = map(ro + rd * t);
        res = min(res, k * h / t);
        t += clamp(h, 0.01, 0.2);
        if (res < 0.001 || t > 10.0) break;
    }
    return clamp(res, 0.0, 1.0);
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    vec3 ro = vec3(0.0, 1.5, -5.0), ta = vec3(0.0, 1.0, 0.0);
    vec3 ww = normalize(ta - ro), uu = normalize(cross(ww, vec3(0.0, 1.0, 0.0))), vv = cross(uu, ww);
    vec3 rd = normalize(mat3(uu, vv, ww) * vec3(uv, 1.8));
    float t = 0.0;
    for (int i = 0; i < MAX_STEPS; i++) {
        float d = map(ro + rd * t);
        if (d < SURF_EPS || t > MAX_DIST) break;
        t += d;
    }
    vec3 col = vec3(0.6, 0.7, 0.9) - rd.y * 0.4;
    if (t < MAX_DIST) {
        vec3 p = ro + rd * t, n = calcNormal(p), l = normalize(vec3(0.6, 0.8, -0.4));
        float dif = clamp(dot(n, l), 0.0, 1.0) * softShadow(p, l, 8.0);
        col = vec3(0.9, 0.8, 0.7) * dif + vec3(0.1, 0.15, 0.2) * (0.5 + 0.5 * n.y);
        col = mix(col, vec3(0.6, 0.7, 0.9), 1.0 - exp(-0.002 * t * t));
    }
    fragColor = vec4(pow(col, vec3(0.4545)), 1.0);
}
