// exercises: 8.3 floatBitsToInt, floatBitsToUint, intBitsToFloat, uintBitsToFloat, every overload
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 p = fragCoord / iResolution.xy;
    int n = iFrame % 7;
    uint m = uint(iFrame) % 5u;
    float s = 0.0;
    { int r = floatBitsToInt((p.x * 0.25)); s += float(r); }
    { uint r = floatBitsToUint((p.x * 0.25)); s += float(r); }
    { float r = intBitsToFloat((n + 1)); s += r; }
    { float r = uintBitsToFloat((m + 1u)); s += r; }
    { ivec2 r = floatBitsToInt(vec2(p.x * 0.25, p.y)); s += dot(vec2(r), vec2(1.0)); }
    { uvec2 r = floatBitsToUint(vec2(p.x * 0.25, p.y)); s += dot(vec2(r), vec2(1.0)); }
    { vec2 r = intBitsToFloat(ivec2(n + 1)); s += dot(r, vec2(1.0)); }
    { vec2 r = uintBitsToFloat(uvec2(m + 1u)); s += dot(r, vec2(1.0)); }
    { ivec3 r = floatBitsToInt(vec3(p, 0.25)); s += dot(vec3(r), vec3(1.0)); }
    { uvec3 r = floatBitsToUint(vec3(p, 0.25)); s += dot(vec3(r), vec3(1.0)); }
    { vec3 r = intBitsToFloat(ivec3(n + 1)); s += dot(r, vec3(1.0)); }
    { vec3 r = uintBitsToFloat(uvec3(m + 1u)); s += dot(r, vec3(1.0)); }
    { ivec4 r = floatBitsToInt(vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = floatBitsToUint(vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(vec4(r), vec4(1.0)); }
    { vec4 r = intBitsToFloat(ivec4(n + 1)); s += dot(r, vec4(1.0)); }
    { vec4 r = uintBitsToFloat(uvec4(m + 1u)); s += dot(r, vec4(1.0)); }
    fragColor = vec4(vec3(fract(s)), 1.0);
}
