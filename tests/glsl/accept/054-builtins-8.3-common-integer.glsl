// exercises: 8.3 abs, sign (genIType) and min, max, clamp (genIType, genUType, with scalar forms)
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 p = fragCoord / iResolution.xy;
    int n = iFrame % 7;
    uint m = uint(iFrame) % 5u;
    float s = 0.0;
    { int r = abs((n + 1)); s += float(r); }
    { int r = sign((n + 1)); s += float(r); }
    { ivec2 r = abs(ivec2(n + 1)); s += dot(vec2(r), vec2(1.0)); }
    { ivec2 r = sign(ivec2(n + 1)); s += dot(vec2(r), vec2(1.0)); }
    { ivec3 r = abs(ivec3(n + 1)); s += dot(vec3(r), vec3(1.0)); }
    { ivec3 r = sign(ivec3(n + 1)); s += dot(vec3(r), vec3(1.0)); }
    { ivec4 r = abs(ivec4(n + 1)); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = sign(ivec4(n + 1)); s += dot(vec4(r), vec4(1.0)); }
    { int r = min((n + 1), (n + 2)); s += float(r); }
    { int r = max((n + 1), (n + 2)); s += float(r); }
    { int r = clamp((n + 1), (n + 2), (n + 3)); s += float(r); }
    { ivec2 r = min(ivec2(n + 1), ivec2(n + 2)); s += dot(vec2(r), vec2(1.0)); }
    { ivec2 r = max(ivec2(n + 1), ivec2(n + 2)); s += dot(vec2(r), vec2(1.0)); }
    { ivec2 r = clamp(ivec2(n + 1), ivec2(n + 2), ivec2(n + 3)); s += dot(vec2(r), vec2(1.0)); }
    { ivec2 r = min(ivec2(n + 1), 1); s += dot(vec2(r), vec2(1.0)); }
    { ivec2 r = max(ivec2(n + 1), 1); s += dot(vec2(r), vec2(1.0)); }
    { ivec2 r = clamp(ivec2(n + 1), 1, 3); s += dot(vec2(r), vec2(1.0)); }
    { ivec3 r = min(ivec3(n + 1), ivec3(n + 2)); s += dot(vec3(r), vec3(1.0)); }
    { ivec3 r = max(ivec3(n + 1), ivec3(n + 2)); s += dot(vec3(r), vec3(1.0)); }
    { ivec3 r = clamp(ivec3(n + 1), ivec3(n + 2), ivec3(n + 3)); s += dot(vec3(r), vec3(1.0)); }
    { ivec3 r = min(ivec3(n + 1), 1); s += dot(vec3(r), vec3(1.0)); }
    { ivec3 r = max(ivec3(n + 1), 1); s += dot(vec3(r), vec3(1.0)); }
    { ivec3 r = clamp(ivec3(n + 1), 1, 3); s += dot(vec3(r), vec3(1.0)); }
    { ivec4 r = min(ivec4(n + 1), ivec4(n + 2)); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = max(ivec4(n + 1), ivec4(n + 2)); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = clamp(ivec4(n + 1), ivec4(n + 2), ivec4(n + 3)); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = min(ivec4(n + 1), 1); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = max(ivec4(n + 1), 1); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = clamp(ivec4(n + 1), 1, 3); s += dot(vec4(r), vec4(1.0)); }
    { uint r = min((m + 1u), (m + 2u)); s += float(r); }
    { uint r = max((m + 1u), (m + 2u)); s += float(r); }
    { uint r = clamp((m + 1u), (m + 2u), (m + 3u)); s += float(r); }
    { uvec2 r = min(uvec2(m + 1u), uvec2(m + 2u)); s += dot(vec2(r), vec2(1.0)); }
    { uvec2 r = max(uvec2(m + 1u), uvec2(m + 2u)); s += dot(vec2(r), vec2(1.0)); }
    { uvec2 r = clamp(uvec2(m + 1u), uvec2(m + 2u), uvec2(m + 3u)); s += dot(vec2(r), vec2(1.0)); }
    { uvec2 r = min(uvec2(m + 1u), 1u); s += dot(vec2(r), vec2(1.0)); }
    { uvec2 r = max(uvec2(m + 1u), 1u); s += dot(vec2(r), vec2(1.0)); }
    { uvec2 r = clamp(uvec2(m + 1u), 1u, 3u); s += dot(vec2(r), vec2(1.0)); }
    { uvec3 r = min(uvec3(m + 1u), uvec3(m + 2u)); s += dot(vec3(r), vec3(1.0)); }
    { uvec3 r = max(uvec3(m + 1u), uvec3(m + 2u)); s += dot(vec3(r), vec3(1.0)); }
    { uvec3 r = clamp(uvec3(m + 1u), uvec3(m + 2u), uvec3(m + 3u)); s += dot(vec3(r), vec3(1.0)); }
    { uvec3 r = min(uvec3(m + 1u), 1u); s += dot(vec3(r), vec3(1.0)); }
    { uvec3 r = max(uvec3(m + 1u), 1u); s += dot(vec3(r), vec3(1.0)); }
    { uvec3 r = clamp(uvec3(m + 1u), 1u, 3u); s += dot(vec3(r), vec3(1.0)); }
    { uvec4 r = min(uvec4(m + 1u), uvec4(m + 2u)); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = max(uvec4(m + 1u), uvec4(m + 2u)); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = clamp(uvec4(m + 1u), uvec4(m + 2u), uvec4(m + 3u)); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = min(uvec4(m + 1u), 1u); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = max(uvec4(m + 1u), 1u); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = clamp(uvec4(m + 1u), 1u, 3u); s += dot(vec4(r), vec4(1.0)); }
    fragColor = vec4(vec3(fract(s)), 1.0);
}
