// exercises: 6.1 prototypes before definitions (also with unnamed parameters), overloads by vector size and by base type, in/out/inout/const in parameters, void functions with early return, calls in any order
float shade(vec2 p);
float shade(vec3 p);
float shade(float, float);
float hash(float x) { return fract(sin(x) * 43758.5453); }
float hash(vec2 p) { return fract(sin(dot(p, vec2(12.9898, 78.233))) * 43758.5453); }
float hash(int i) { return hash(float(i)); }
float hash(uint u) { return hash(float(u)); }
float hash(bool b) { return b ? 1.0 : 0.0; }
void split(in vec2 p, out float x, inout float acc, const in float k) {
    x = p.x * k;
    acc += p.y;
    if (acc > 10.0) return;
    acc *= 0.5;
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 p = fragCoord / iResolution.xy;
    float x, acc = 1.0;
    split(p, x, acc, 2.0);
    fragColor = vec4(shade(p) + shade(vec3(p, 1.0)) + shade(p.x, p.y), hash(p.x) + hash(p), hash(iFrame) + hash(uint(iFrame)) + hash(true), x + acc);
}
float shade(vec2 p) { return length(p); }
float shade(vec3 p) { return length(p); }
float shade(float a, float b) { return a * b; }
