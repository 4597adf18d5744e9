// exercises: 8.5 geometric functions, every genType overload
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 p = fragCoord / iResolution.xy;
    int n = iFrame % 7;
    uint m = uint(iFrame) % 5u;
    float s = 0.0;
    { float r = length((p.x * 0.25)); s += r; }
    { float r = distance((p.x * 0.25), (p.x * 0.5)); s += r; }
    { float r = dot((p.x * 0.25), (p.x * 0.5)); s += r; }
    { float r = normalize((p.x * 0.25)); s += r; }
    { float r = faceforward((p.x * 0.25), (p.x * 0.5), (p.x * 0.75)); s += r; }
    { float r = reflect((p.x * 0.25), (p.x * 0.5)); s += r; }
    { float r = refract((p.x * 0.25), (p.x * 0.5), 0.66); s += r; }
    { float r = length(vec2(p.x * 0.25, p.y)); s += r; }
    { float r = distance(vec2(p.x * 0.25, p.y), vec2(p.x * 0.5, p.y)); s += r; }
    { float r = dot(vec2(p.x * 0.25, p.y), vec2(p.x * 0.5, p.y)); s += r; }
    { vec2 r = normalize(vec2(p.x * 0.25, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = faceforward(vec2(p.x * 0.25, p.y), vec2(p.x * 0.5, p.y), vec2(p.x * 0.75, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = reflect(vec2(p.x * 0.25, p.y), vec2(p.x * 0.5, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = refract(vec2(p.x * 0.25, p.y), vec2(p.x * 0.5, p.y), 0.66); s += dot(r, vec2(1.0)); }
    { float r = length(vec3(p, 0.25)); s += r; }
    { float r = distance(vec3(p, 0.25), vec3(p, 0.5)); s += r; }
    { float r = dot(vec3(p, 0.25), vec3(p, 0.5)); s += r; }
    { vec3 r = normalize(vec3(p, 0.25)); s += dot(r, vec3(1.0)); }
    { vec3 r = faceforward(vec3(p, 0.25), vec3(p, 0.5), vec3(p, 0.75)); s += dot(r, vec3(1.0)); }
    { vec3 r = reflect(vec3(p, 0.25), vec3(p, 0.5)); s += dot(r, vec3(1.0)); }
    { vec3 r = refract(vec3(p, 0.25), vec3(p, 0.5), 0.66); s += dot(r, vec3(1.0)); }
    { float r = length(vec4(p.x, p.y, p.x + p.y, 0.25)); s += r; }
    { float r = distance(vec4(p.x, p.y, p.x + p.y, 0.25), vec4(p.x, p.y, p.x + p.y, 0.5)); s += r; }
    { float r = dot(vec4(p.x, p.y, p.x + p.y, 0.25), vec4(p.x, p.y, p.x + p.y, 0.5)); s += r; }
    { vec4 r = normalize(vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(r, vec4(1.0)); }
    { vec4 r = faceforward(vec4(p.x, p.y, p.x + p.y, 0.25), vec4(p.x, p.y, p.x + p.y, 0.5), vec4(p.x, p.y, p.x + p.y, 0.75)); s += dot(r, vec4(1.0)); }
    { vec4 r = reflect(vec4(p.x, p.y, p.x + p.y, 0.25), vec4(p.x, p.y, p.x + p.y, 0.5)); s += dot(r, vec4(1.0)); }
    { vec4 r = refract(vec4(p.x, p.y, p.x + p.y, 0.25), vec4(p.x, p.y, p.x + p.y, 0.5), 0.66); s += dot(r, vec4(1.0)); }
    { vec3 r = cross(vec3(p, 0.25), vec3(p, 0.5)); s += dot(r, vec3(1.0)); }
    fragColor = vec4(vec3(fract(s)), 1.0);
}
