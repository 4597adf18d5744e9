// exercises: 8.2 exponential functions, every genType overload
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 p = fragCoord / iResolution.xy;
    int n = iFrame % 7;
    uint m = uint(iFrame) % 5u;
    float s = 0.0;
    { float r = pow((p.x * 0.25), (p.x * 0.5)); s += r; }
    { float r = exp((p.x * 0.25)); s += r; }
    { float r = log((p.x * 0.25)); s += r; }
    { float r = exp2((p.x * 0.25)); s += r; }
    { float r = log2((p.x * 0.25)); s += r; }
    { float r = sqrt((p.x * 0.25)); s += r; }
    { float r = inversesqrt((p.x * 0.25)); s += r; }
    { vec2 r = pow(vec2(p.x * 0.25, p.y), vec2(p.x * 0.5, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = exp(vec2(p.x * 0.25, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = log(vec2(p.x * 0.25, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = exp2(vec2(p.x * 0.25, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = log2(vec2(p.x * 0.25, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = sqrt(vec2(p.x * 0.25, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = inversesqrt(vec2(p.x * 0.25, p.y)); s += dot(r, vec2(1.0)); }
    { vec3 r = pow(vec3(p, 0.25), vec3(p, 0.5)); s += dot(r, vec3(1.0)); }
    { vec3 r = exp(vec3(p, 0.25)); s += dot(r, vec3(1.0)); }
    { vec3 r = log(vec3(p, 0.25)); s += dot(r, vec3(1.0)); }
    { vec3 r = exp2(vec3(p, 0.25)); s += dot(r, vec3(1.0)); }
    { vec3 r = log2(vec3(p, 0.25)); s += dot(r, vec3(1.0)); }
    { vec3 r = sqrt(vec3(p, 0.25)); s += dot(r, vec3(1.0)); }
    { vec3 r = inversesqrt(vec3(p, 0.25)); s += dot(r, vec3(1.0)); }
    { vec4 r = pow(vec4(p.x, p.y, p.x + p.y, 0.25), vec4(p.x, p.y, p.x + p.y, 0.5)); s += dot(r, vec4(1.0)); }
    { vec4 r = exp(vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(r, vec4(1.0)); }
    { vec4 r = log(vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(r, vec4(1.0)); }
    { vec4 r = exp2(vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(r, vec4(1.0)); }
    { vec4 r = log2(vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(r, vec4(1.0)); }
    { vec4 r = sqrt(vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(r, vec4(1.0)); }
    { vec4 r = inversesqrt(vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(r, vec4(1.0)); }
    fragColor = vec4(vec3(fract(s)), 1.0);
}
