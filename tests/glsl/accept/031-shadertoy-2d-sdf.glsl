// exercises: a typical ShaderToy 2D program: signed distance functions, antialiasing with fwidth and smoothstep, polar repetition with atan and mod, iMouse interaction, a #define switch
#define SHOW_GRID 1
float sdCircle(vec2 p, float r) { return length(p) - r; }
float sdSegment(vec2 p, vec2 a, vec2 b) {
    vec2 pa = p - a, ba = b - a;
    float h = clamp(dot(pa, ba) / dot(ba, ba), 0.0, 1.0);
    return length(pa - ba * h);
}
vec2 polarRepeat(vec2 p, float n) {
    float an = 6.2831853 / n;
    float a = mod(atan(p.y, p.x) + an * 0.5, an) - an * 0.5;
    return length(p) * vec2(cos(a), sin(a));
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 p = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    vec2 m = (2.0 * iMouse.xy - iResolution.xy) / iResolution.y;
    float d = sdCircle(polarRepeat(p, 7.0) - vec2(0.6, 0.0), 0.1);
    d = min(d, sdSegment(p, vec2(0.0), m));
    float w = fwidth(d);
    vec3 col = mix(vec3(1.0), vec3(0.2, 0.5, 0.9), smoothstep(-w, w, d));
    col *= 1.0 - exp(-6.0 * abs(d)) * 0.3;
#if SHOW_GRID
    vec2 g = abs(fract(p * 5.0) - 0.5);
    col *= 0.9 + 0.1 * smoothstep(0.0, 0.05, min(g.x, g.y));
#endif
    fragColor = vec4(col, 1.0);
}
