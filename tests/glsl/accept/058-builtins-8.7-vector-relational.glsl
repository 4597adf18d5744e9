// exercises: 8.7 vector relational functions, every vec/ivec/uvec/bvec overload
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 p = fragCoord / iResolution.xy;
    int n = iFrame % 7;
    uint m = uint(iFrame) % 5u;
    float s = 0.0;
    { bvec2 r = lessThan(vec2(p.x * 0.25, p.y), vec2(p.x * 0.5, p.y)); s += (any(r) ? 1.0 : 0.0); }
    { bvec2 r = lessThanEqual(vec2(p.x * 0.25, p.y), vec2(p.x * 0.5, p.y)); s += (any(r) ? 1.0 : 0.0); }
    { bvec2 r = greaterThan(vec2(p.x * 0.25, p.y), vec2(p.x * 0.5, p.y)); s += (any(r) ? 1.0 : 0.0); }
    { bvec2 r = greaterThanEqual(vec2(p.x * 0.25, p.y), vec2(p.x * 0.5, p.y)); s += (any(r) ? 1.0 : 0.0); }
    { bvec2 r = equal(vec2(p.x * 0.25, p.y), vec2(p.x * 0.5, p.y)); s += (any(r) ? 1.0 : 0.0); }
    { bvec2 r = notEqual(vec2(p.x * 0.25, p.y), vec2(p.x * 0.5, p.y)); s += (any(r) ? 1.0 : 0.0); }
    { bvec2 r = lessThan(ivec2(n + 1), ivec2(n + 2)); s += (any(r) ? 1.0 : 0.0); }
    { bvec2 r = lessThanEqual(ivec2(n + 1), ivec2(n + 2)); s += (any(r) ? 1.0 : 0.0); }
    { bvec2 r = greaterThan(ivec2(n + 1), ivec2(n + 2)); s += (any(r) ? 1.0 : 0.0); }
    { bvec2 r = greaterThanEqual(ivec2(n + 1), ivec2(n + 2)); s += (any(r) ? 1.0 : 0.0); }
    { bvec2 r = equal(ivec2(n + 1), ivec2(n + 2)); s += (any(r) ? 1.0 : 0.0); }
    { bvec2 r = notEqual(ivec2(n + 1), ivec2(n + 2)); s += (any(r) ? 1.0 : 0.0); }
    { bvec2 r = lessThan(uvec2(m + 1u), uvec2(m + 2u)); s += (any(r) ? 1.0 : 0.0); }
    { bvec2 r = lessThanEqual(uvec2(m + 1u), uvec2(m + 2u)); s += (any(r) ? 1.0 : 0.0); }
    { bvec2 r = greaterThan(uvec2(m + 1u), uvec2(m + 2u)); s += (any(r) ? 1.0 : 0.0); }
    { bvec2 r = greaterThanEqual(uvec2(m + 1u), uvec2(m + 2u)); s += (any(r) ? 1.0 : 0.0); }
    { bvec2 r = equal(uvec2(m + 1u), uvec2(m + 2u)); s += (any(r) ? 1.0 : 0.0); }
    { bvec2 r = notEqual(uvec2(m + 1u), uvec2(m + 2u)); s += (any(r) ? 1.0 : 0.0); }
    { bvec2 r = equal(greaterThan(vec2(p.x * 0.25, p.y), vec2(0.25)), greaterThan(vec2(p.x * 0.5, p.y), vec2(0.5))); s += (any(r) ? 1.0 : 0.0); }
    { bvec2 r = notEqual(greaterThan(vec2(p.x * 0.25, p.y), vec2(0.25)), greaterThan(vec2(p.x * 0.5, p.y), vec2(0.5))); s += (any(r) ? 1.0 : 0.0); }
    { bool r = any(greaterThan(vec2(p.x * 0.25, p.y), vec2(0.25))); s += (r ? 1.0 : 0.0); }
    { bool r = all(greaterThan(vec2(p.x * 0.25, p.y), vec2(0.25))); s += (r ? 1.0 : 0.0); }
    { bvec2 r = not(greaterThan(vec2(p.x * 0.25, p.y), vec2(0.25))); s += (any(r) ? 1.0 : 0.0); }
    { bvec3 r = lessThan(vec3(p, 0.25), vec3(p, 0.5)); s += (any(r) ? 1.0 : 0.0); }
    { bvec3 r = lessThanEqual(vec3(p, 0.25), vec3(p, 0.5)); s += (any(r) ? 1.0 : 0.0); }
    { bvec3 r = greaterThan(vec3(p, 0.25), vec3(p, 0.5)); s += (any(r) ? 1.0 : 0.0); }
    { bvec3 r = greaterThanEqual(vec3(p, 0.25), vec3(p, 0.5)); s += (any(r) ? 1.0 : 0.0); }
    { bvec3 r = equal(vec3(p, 0.25), vec3(p, 0.5)); s += (any(r) ? 1.0 : 0.0); }
    { bvec3 r = notEqual(vec3(p, 0.25), vec3(p, 0.5)); s += (any(r) ? 1.0 : 0.0); }
    { bvec3 r = lessThan(ivec3(n + 1), ivec3(n + 2)); s += (any(r) ? 1.0 : 0.0); }
    { bvec3 r = lessThanEqual(ivec3(n + 1), ivec3(n + 2)); s += (any(r) ? 1.0 : 0.0); }
    { bvec3 r = greaterThan(ivec3(n + 1), ivec3(n + 2)); s += (any(r) ? 1.0 : 0.0); }
    { bvec3 r = greaterThanEqual(ivec3(n + 1), ivec3(n + 2)); s += (any(r) ? 1.0 : 0.0); }
    { bvec3 r = equal(ivec3(n + 1), ivec3(n + 2)); s += (any(r) ? 1.0 : 0.0); }
    { bvec3 r = notEqual(ivec3(n + 1), ivec3(n + 2)); s += (any(r) ? 1.0 : 0.0); }
    { bvec3 r = lessThan(uvec3(m + 1u), uvec3(m + 2u)); s += (any(r) ? 1.0 : 0.0); }
    { bvec3 r = lessThanEqual(uvec3(m + 1u), uvec3(m + 2u)); s += (any(r) ? 1.0 : 0.0); }
    { bvec3 r = greaterThan(uvec3(m + 1u), uvec3(m + 2u)); s += (any(r) ? 1.0 : 0.0); }
    { bvec3 r = greaterThanEqual(uvec3(m + 1u), uvec3(m + 2u)); s += (any(r) ? 1.0 : 0.0); }
    { bvec3 r = equal(uvec3(m + 1u), uvec3(m + 2u)); s += (any(r) ? 1.0 : 0.0); }
    { bvec3 r = notEqual(uvec3(m + 1u), uvec3(m + 2u)); s += (any(r) ? 1.0 : 0.0); }
    { bvec3 r = equal(greaterThan(vec3(p, 0.25), vec3(0.25)), greaterThan(vec3(p, 0.5), vec3(0.5))); s += (any(r) ? 1.0 : 0.0); }
    { bvec3 r = notEqual(greaterThan(vec3(p, 0.25), vec3(0.25)), greaterThan(vec3(p, 0.5), vec3(0.5))); s += (any(r) ? 1.0 : 0.0); }
    { bool r = any(greaterThan(vec3(p, 0.25), vec3(0.25))); s += (r ? 1.0 : 0.0); }
    { bool r = all(greaterThan(vec3(p, 0.25), vec3(0.25))); s += (r ? 1.0 : 0.0); }
    { bvec3 r = not(greaterThan(vec3(p, 0.25), vec3(0.25))); s += (any(r) ? 1.0 : 0.0); }
    { bvec4 r = lessThan(vec4(p.x, p.y, p.x + p.y, 0.25), vec4(p.x, p.y, p.x + p.y, 0.5)); s += (any(r) ? 1.0 : 0.0); }
    { bvec4 r = lessThanEqual(vec4(p.x, p.y, p.x + p.y, 0.25), vec4(p.x, p.y, p.x + p.y, 0.5)); s += (any(r) ? 1.0 : 0.0); }
    { bvec4 r = greaterThan(vec4(p.x, p.y, p.x + p.y, 0.25), vec4(p.x, p.y, p.x + p.y, 0.5)); s += (any(r) ? 1.0 : 0.0); }
    { bvec4 r = greaterThanEqual(vec4(p.x, p.y, p.x + p.y, 0.25), vec4(p.x, p.y, p.x + p.y, 0.5)); s += (any(r) ? 1.0 : 0.0); }
    { bvec4 r = equal(vec4(p.x, p.y, p.x + p.y, 0.25), vec4(p.x, p.y, p.x + p.y, 0.5)); s += (any(r) ? 1.0 : 0.0); }
    { bvec4 r = notEqual(vec4(p.x, p.y, p.x + p.y, 0.25), vec4(p.x, p.y, p.x + p.y, 0.5)); s += (any(r) ? 1.0 : 0.0); }
    { bvec4 r = lessThan(ivec4(n + 1), ivec4(n + 2)); s += (any(r) ? 1.0 : 0.0); }
    { bvec4 r = lessThanEqual(ivec4(n + 1), ivec4(n + 2)); s += (any(r) ? 1.0 : 0.0); }
    { bvec4 r = greaterThan(ivec4(n + 1), ivec4(n + 2)); s += (any(r) ? 1.0 : 0.0); }
    { bvec4 r = greaterThanEqual(ivec4(n + 1), ivec4(n + 2)); s += (any(r) ? 1.0 : 0.0); }
    { bvec4 r = equal(ivec4(n + 1), ivec4(n + 2)); s += (any(r) ? 1.0 : 0.0); }
    { bvec4 r = notEqual(ivec4(n + 1), ivec4(n + 2)); s += (any(r) ? 1.0 : 0.0); }
    { bvec4 r = lessThan(uvec4(m + 1u), uvec4(m + 2u)); s += (any(r) ? 1.0 : 0.0); }
    { bvec4 r = lessThanEqual(uvec4(m + 1u), uvec4(m + 2u)); s += (any(r) ? 1.0 : 0.0); }
    { bvec4 r = greaterThan(uvec4(m + 1u), uvec4(m + 2u)); s += (any(r) ? 1.0 : 0.0); }
    { bvec4 r = greaterThanEqual(uvec4(m + 1u), uvec4(m + 2u)); s += (any(r) ? 1.0 : 0.0); }
    { bvec4 r = equal(uvec4(m + 1u), uvec4(m + 2u)); s += (any(r) ? 1.0 : 0.0); }
    { bvec4 r = notEqual(uvec4(m + 1u), uvec4(m + 2u)); s += (any(r) ? 1.0 : 0.0); }
    { bvec4 r = equal(greaterThan(vec4(p.x, p.y, p.x + p.y, 0.25), vec4(0.25)), greaterThan(vec4(p.x, p.y, p.x + p.y, 0.5), vec4(0.5))); s += (any(r) ? 1.0 : 0.0); }
    { bvec4 r = notEqual(greaterThan(vec4(p.x, p.y, p.x + p.y, 0.25), vec4(0.25)), greaterThan(vec4(p.x, p.y, p.x + p.y, 0.5), vec4(0.5))); s += (any(r) ? 1.0 : 0.0); }
    { bool r = any(greaterThan(vec4(p.x, p.y, p.x + p.y, 0.25), vec4(0.25))); s += (r ? 1.0 : 0.0); }
    { bool r = all(greaterThan(vec4(p.x, p.y, p.x + p.y, 0.25), vec4(0.25))); s += (r ? 1.0 : 0.0); }
    { bvec4 r = not(greaterThan(vec4(p.x, p.y, p.x + p.y, 0.25), vec4(0.25))); s += (any(r) ? 1.0 : 0.0); }
    fragColor = vec4(vec3(fract(s)), 1.0);
}
