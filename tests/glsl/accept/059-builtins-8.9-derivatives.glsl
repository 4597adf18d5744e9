// exercises: 8.9 dFdx, dFdy, fwidth on every genType
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 p = fragCoord / iResolution.xy;
    int n = iFrame % 7;
    uint m = uint(iFrame) % 5u;
    float s = 0.0;
    { float r = dFdx((p.x * 0.25)); s += r; }
    { float r = dFdy((p.x * 0.25)); s += r; }
    { float r = fwidth((p.x * 0.25)); s += r; }
    { vec2 r = dFdx(vec2(p.x * 0.25, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = dFdy(vec2(p.x * 0.25, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = fwidth(vec2(p.x * 0.25, p.y)); s += dot(r, vec2(1.0)); }
    { vec3 r = dFdx(vec3(p, 0.25)); s += dot(r, vec3(1.0)); }
    { vec3 r = dFdy(vec3(p, 0.25)); s += dot(r, vec3(1.0)); }
    { vec3 r = fwidth(vec3(p, 0.25)); s += dot(r, vec3(1.0)); }
    { vec4 r = dFdx(vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(r, vec4(1.0)); }
    { vec4 r = dFdy(vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(r, vec4(1.0)); }
    { vec4 r = fwidth(vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(r, vec4(1.0)); }
    fragColor = vec4(vec3(fract(s)), 1.0);
}
