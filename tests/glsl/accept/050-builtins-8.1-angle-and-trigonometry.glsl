// exercises: 8.1 angle and trigonometry functions, every genType overload
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 p = fragCoord / iResolution.xy;
    int n = iFrame % 7;
    uint m = uint(iFrame) % 5u;
    float s = 0.0;
    { float r = radians((p.x * 0.25)); s += r; }
    { float r = degrees((p.x * 0.25)); s += r; }
    { float r = sin((p.x * 0.25)); s += r; }
    { float r = cos((p.x * 0.25)); s += r; }
    { float r = tan((p.x * 0.25)); s += r; }
    { float r = asin((p.x * 0.25)); s += r; }
    { float r = acos((p.x * 0.25)); s += r; }
    { float r = atan((p.x * 0.25)); s += r; }
    { float r = sinh((p.x * 0.25)); s += r; }
    { float r = cosh((p.x * 0.25)); s += r; }
    { float r = tanh((p.x * 0.25)); s += r; }
    { float r = asinh((p.x * 0.25)); s += r; }
    { float r = acosh((p.x * 0.25)); s += r; }
    { float r = atanh((p.x * 0.25)); s += r; }
    { float r = atan((p.x * 0.25), (p.x * 0.5)); s += r; }
    { vec2 r = radians(vec2(p.x * 0.25, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = degrees(vec2(p.x * 0.25, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = sin(vec2(p.x * 0.25, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = cos(vec2(p.x * 0.25, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = tan(vec2(p.x * 0.25, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = asin(vec2(p.x * 0.25, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = acos(vec2(p.x * 0.25, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = atan(vec2(p.x * 0.25, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = sinh(vec2(p.x * 0.25, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = cosh(vec2(p.x * 0.25, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = tanh(vec2(p.x * 0.25, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = asinh(vec2(p.x * 0.25, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = acosh(vec2(p.x * 0.25, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = atanh(vec2(p.x * 0.25, p.y)); s += dot(r, vec2(1.0)); }
    { vec2 r = atan(vec2(p.x * 0.25, p.y), vec2(p.x * 0.5, p.y)); s += dot(r, vec2(1.0)); }
    { vec3 r = radians(vec3(p, 0.25)); s += dot(r, vec3(1.0)); }
    { vec3 r = degrees(vec3(p, 0.25)); s += dot(r, vec3(1.0)); }
    { vec3 r = sin(vec3(p, 0.25)); s += dot(r, vec3(1.0)); }
    { vec3 r = cos(vec3(p, 0.25)); s += dot(r, vec3(1.0)); }
    { vec3 r = tan(vec3(p, 0.25)); s += dot(r, vec3(1.0)); }
    { vec3 r = asin(vec3(p, 0.25)); s += dot(r, vec3(1.0)); }
    { vec3 r = acos(vec3(p, 0.25)); s += dot(r, vec3(1.0)); }
    { vec3 r = atan(vec3(p, 0.25)); s += dot(r, vec3(1.0)); }
    { vec3 r = sinh(vec3(p, 0.25)); s += dot(r, vec3(1.0)); }
    { vec3 r = cosh(vec3(p, 0.25)); s += dot(r, vec3(1.0)); }
    { vec3 r = tanh(vec3(p, 0.25)); s += dot(r, vec3(1.0)); }
    { vec3 r = asinh(vec3(p, 0.25)); s += dot(r, vec3(1.0)); }
    { vec3 r = acosh(vec3(p, 0.25)); s += dot(r, vec3(1.0)); }
    { vec3 r = atanh(vec3(p, 0.25)); s += dot(r, vec3(1.0)); }
    { vec3 r = atan(vec3(p, 0.25), vec3(p, 0.5)); s += dot(r, vec3(1.0)); }
    { vec4 r = radians(vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(r, vec4(1.0)); }
    { vec4 r = degrees(vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(r, vec4(1.0)); }
    { vec4 r = sin(vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(r, vec4(1.0)); }
    { vec4 r = cos(vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(r, vec4(1.0)); }
    { vec4 r = tan(vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(r, vec4(1.0)); }
    { vec4 r = asin(vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(r, vec4(1.0)); }
    { vec4 r = acos(vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(r, vec4(1.0)); }
    { vec4 r = atan(vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(r, vec4(1.0)); }
    { vec4 r = sinh(vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(r, vec4(1.0)); }
    { vec4 r = cosh(vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(r, vec4(1.0)); }
    { vec4 r = tanh(vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(r, vec4(1.0)); }
    { vec4 r = asinh(vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(r, vec4(1.0)); }
    { vec4 r = acosh(vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(r, vec4(1.0)); }
    { vec4 r = atanh(vec4(p.x, p.y, p.x + p.y, 0.25)); s += dot(r, vec4(1.0)); }
    { vec4 r = atan(vec4(p.x, p.y, p.x + p.y, 0.25), vec4(p.x, p.y, p.x + p.y, 0.5)); s += dot(r, vec4(1.0)); }
    fragColor = vec4(vec3(fract(s)), 1.0);
}
