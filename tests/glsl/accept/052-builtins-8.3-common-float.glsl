// exercises: 8.3 common functions on genType, including the scalar second-argument forms and mix with genBType
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 p = fragCoord / iResolution.xy;
    int n = iFrame % 7;
    uint m = uint(iFrame) % 5u;
    float s = 0.0;
    { float r = abs((p.x * 0.25)); s += r; }
    { float r = sign((p.x * 0.25)); s += r; }
    { float r = floor((p.x * 0.25)); s += r; }
    { float r = trunc((p.x * 0.25)); s += r; }
    { float r = round((p.x * 0.25)); s += r; }
    { float r = roundEven((p.x * 0.25)); s += r; }
    { float r = ceil((p.x * 0.25)); s += r; }
    { float r = fract((p.x * 0.25)); s += r; }
    { float r = mod((p.x * 0.25), (p.x * 0.5)); s += r; }
    { float r = min((p.x * 0.25), (p.x * 0.5)); s += r; }
    { float r = max((p.x * 0.25), (p.x * 0.5)); s += r; }
    { float r = clamp((p.x * 0.25), (p.x * 0.5), (p.x * 0.75)); s += r; }
    { float r = mix((p.x * 0.25), (p.x * 0.5), (p.x * 0.75)); s += r; }
    { float r = step((p.x * 0.25), (p.x * 0.5)); s += r; }
    { float r = smoothstep((p.x * 0.25), (p.x * 0.5), (p.x * 0.75)); s += r; }
    { float r = mix((p.x * 0.25), (p.x * 0.5), (p.x > 0.25)); s += r; }
    { bool r = isnan((p.x * 0.25)); s += (r ? 1.0 : 0.0); }
    { bool r = isinf((p.x * 0.25)); s += (r ? 1.0 : 0.0); }
    { vec2 r = abs(vec2(p.x * 0.25, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = sign(vec2(p.x * 0.25, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = floor(vec2(p.x * 0.25, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = trunc(vec2(p.x * 0.25, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = round(vec2(p.x * 0.25, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = roundEven(vec2(p.x * 0.25, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = ceil(vec2(p.x * 0.25, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = fract(vec2(p.x * 0.25, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = mod(vec2(p.x * 0.25, p.y), vec2(p.x * 0.5, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = min(vec2(p.x * 0.25, p.y), vec2(p.x * 0.5, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = max(vec2(p.x * 0.25, p.y), vec2(p.x * 0.5, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = clamp(vec2(p.x * 0.25, p.y), vec2(p.x * 0.5, p.y), vec2(p.x * 0.75, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = mix(vec2(p.x * 0.25, p.y), vec2(p.x * 0.5, p.y), vec2(p.x * 0.75, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = step(vec2(p.x * 0.25, p.y), vec2(p.x * 0.5, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = smoothstep(vec2(p.x * 0.25, p.y), vec2(p.x * 0.5, p.y), vec2(p.x * 0.75, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = mod(vec2(p.x * 0.25, p.y), 0.5); s += dot(r, vec2(1.0)); }
    { vec2 r = min(vec2(p.x * 0.25, p.y), 0.5); s += dot(r, vec2(1.0)); }
    { vec2 r = max(vec2(p.x * 0.25, p.y), 0.5); s += dot(r, vec2(1.0)); }
    { vec2 r = clamp(vec2(p.x * 0.25, p.y), 0.25, 0.75); s += dot(r, vec2(1.0)); }
    { vec2 r = mix(vec2(p.x * 0.25, p.y), vec2(p.x * 0.5, p.y), 0.5); s += dot(r, vec2(1.0)); }
    { vec2 r = step(0.5, vec2(p.x * 0.25, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = smoothstep(0.25, 0.75, vec2(p.x * 0.25, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = mix(vec2(p.x * 0.25, p.y), vec2(p.x * 0.5, p.y), greaterThan(vec2(p.x * 0.25, p.y), vec2(0.25))); s += dot(r, vec2(1.0)); }
    { bvec2 r = isnan(vec2(p.x * 0.25, p.y)); s += (any(r) ? 1.0 : 0.0); }
    { bvec2 r = isinf(vec2(p.x * 0.25, p.y)); s += (any(r) ? 1.0 : 0.0); }
    { vec3 r = abs(vec3(p, 0.25)); s += dot(r, vec3(1.0)); }
    { vec3 r = sign(vec3(p, 0.25)); s += dot(r, vec3(1.0)); }
    { vec3 r = floor(vec3(p, 0.25)); s += dot(r, vec3(1.0)); }
    { vec3 r = trunc(vec3(p, 0.25)); s += dot(r, vec3(1.0)); }
    { vec3 r = round(vec3(p, 0.25)); s += dot(r, vec3(1.0)); }
    { vec3 r = roundEven(vec3(p, 0.25)); s += dot(r, vec3(1.0)); }
    { vec3 r = ceil(vec3(p, 0.25)); s += dot(r, vec3(1.0)); }
    { vec3 r = fract(vec3(p, 0.25)); s += dot(r, vec3(1.0)); }
    { vec3 r = mod(vec3(p, 0.25), vec3(p, 0.5)); s += dot(r, vec3(1.0)); }
    { vec3 r = min(vec3(p, 0.25), vec3(p, 0.5)); s += dot(r, vec3(1.0)); }
    { vec3 r = max(vec3(p, 0.25), vec3(p, 0.5)); s += dot(r, vec3(1.0)); }
    { vec3 r = clamp(vec3(p, 0.25), vec3(p, 0.5), vec3(p, 0.75)); s += dot(r, vec3(1.0)); }
    { vec3 r = mix(vec3(p, 0.25), vec3(p, 0.5), vec3(p, 0.75)); s += dot(r, vec3(1.0)); }
    { vec3 r = step(vec3(p, 0.25), vec3(p, 0.5)); s += dot(r, vec3(1.0)); }
    { vec3 r = smoothstep(vec3(p, 0.25), vec3(p, 0.5), vec3(p, 0.75)); s += dot(r, vec3(1.0)); }
    { vec3 r = mod(vec3(p, 0.25), 0.5); s += dot(r, vec3(1.0)); }
    { vec3 r = min(vec3(p, 0.25), 0.5); s += dot(r, vec3(1.0)); }
    { vec3 r = max(vec3(p, 0.25), 0.5); s += dot(r, vec3(1.0)); }
    { vec3 r = clamp(vec3(p, 0.25), 0.25, 0.75); s += dot(r, vec3(1.0)); }
    { vec3 r = mix(vec3(p, 0.25), vec3(p, 0.5), 0.5); s += dot(r, vec3(1.0)); }
    { vec3 r = step(0.5, vec3(p, 0.25)); s += dot(r, vec3(1.0)); }
    { vec3 r = smoothstep(0.25, 0.75, vec3(p, 0.25)); s += dot(r, vec3(1.0)); }
    { vec3 r = mix(vec3(p, 0.25), vec3(p, 0.5), greaterThan(vec3(p, 0.25), vec3(0.25))); s += dot(r, vec3(1.0)); }
    { bvec3 r = isnan(vec3(p, 0.25)); s += (any(r) ? 1.0 : 0.0); }
    { bvec3 r = isinf(vec3(p, 0.25)); s += (any(r) ? 1.0 : 0.0); }
    { vec4 r = abs(vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(r, vec4(1.0)); }
    { vec4 r = sign(vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(r, vec4(1.0)); }
    { vec4 r = floor(vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(r, vec4(1.0)); }
    { vec4 r = trunc(vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(r, vec4(1.0)); }
    { vec4 r = round(vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(r, vec4(1.0)); }
    { vec4 r = roundEven(vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(r, vec4(1.0)); }
    { vec4 r = ceil(vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(r, vec4(1.0)); }
    { vec4 r = fract(vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(r, vec4(1.0)); }
    { vec4 r = mod(vec4(p.x, p.y, p.x + p.y, 0.25), vec4(p.x, p.y, p.x + p.y, 0.5)); s += dot(r, vec4(1.0)); }
    { vec4 r = min(vec4(p.x, p.y, p.x + p.y, 0.25), vec4(p.x, p.y, p.x + p.y, 0.5)); s += dot(r, vec4(1.0)); }
    { vec4 r = max(vec4(p.x, p.y, p.x + p.y, 0.25), vec4(p.x, p.y, p.x + p.y, 0.5)); s += dot(r, vec4(1.0)); }
    { vec4 r = clamp(vec4(p.x, p.y, p.x + p.y, 0.25), vec4(p.x, p.y, p.x + p.y, 0.5), vec4(p.x, p.y, p.x + p.y, 0.75)); s += dot(r, vec4(1.0)); }
    { vec4 r = mix(vec4(p.x, p.y, p.x + p.y, 0.25), vec4(p.x, p.y, p.x + p.y, 0.5), vec4(p.x, p.y, p.x + p.y, 0.75)); s += dot(r, vec4(1.0)); }
    { vec4 r = step(vec4(p.x, p.y, p.x + p.y, 0.25), vec4(p.x, p.y, p.x + p.y, 0.5)); s += dot(r, vec4(1.0)); }
    { vec4 r = smoothstep(vec4(p.x, p.y, p.x + p.y, 0.25), vec4(p.x, p.y, p.x + p.y, 0.5), vec4(p.x, p.y, p.x + p.y, 0.75)); s += dot(r, vec4(1.0)); }
    { vec4 r = mod(vec4(p.x, p.y, p.x + p.y, 0.25), 0.5); s += dot(r, vec4(1.0)); }
    { vec4 r = min(vec4(p.x, p.y, p.x + p.y, 0.25), 0.5); s += dot(r, vec4(1.0)); }
    { vec4 r = max(vec4(p.x, p.y, p.x + p.y, 0.25), 0.5); s += dot(r, vec4(1.0)); }
    { vec4 r = clamp(vec4(p.x, p.y, p.x + p.y, 0.25), 0.25, 0.75); s += dot(r, vec4(1.0)); }
    { vec4 r = mix(vec4(p.x, p.y, p.x + p.y, 0.25), vec4(p.x, p.y, p.x + p.y, 0.5), 0.5); s += dot(r, vec4(1.0)); }
    { vec4 r = step(0.5, vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(r, vec4(1.0)); }
    { vec4 r = smoothstep(0.25, 0.75, vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(r, vec4(1.0)); }
    { vec4 r = mix(vec4(p.x, p.y, p.x + p.y, 0.25), vec4(p.x, p.y, p.x + p.y, 0.5), greaterThan(vec4(p.x, p.y, p.x + p.y, 0.25), vec4(0.25))); s += dot(r, vec4(1.0)); }
    { bvec4 r = isnan(vec4(p.x, p.y, p.x + p.y, 0.25)); s += (any(r) ? 1.0 : 0.0); }
    { bvec4 r = isinf(vec4(p.x, p.y, p.x + p.y, 0.25)); s += (any(r) ? 1.0 : 0.0); }
    fragColor = vec4(vec3(fract(s)), 1.0);
}
