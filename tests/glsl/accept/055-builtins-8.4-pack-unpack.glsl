// exercises: 8.4 floating-point pack and unpack functions
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 p = fragCoord / iResolution.xy;
    int n = iFrame % 7;
    uint m = uint(iFrame) % 5u;
    float s = 0.0;
    { uint r = packSnorm2x16(vec2(p.x * 0.25, p.y)); s += float(r); }
    { vec2 r = unpackSnorm2x16((m + 1u)); s += dot(r, vec2(1.0)); }
    { uint r = packUnorm2x16(vec2(p.x * 0.25, p.y)); s += float(r); }
    { vec2 r = unpackUnorm2x16((m + 1u)); s += dot(r, vec2(1.0)); }
    { uint r = packHalf2x16(vec2(p.x * 0.25, p.y)); s += float(r); }
    { vec2 r = unpackHalf2x16((m + 1u)); s += dot(r, vec2(1.0)); }
    fragColor = vec4(vec3(fract(s)), 1.0);
}
