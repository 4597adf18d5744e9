// exercises: 4.3 global (non-const) variables: uninitialised, initialised with constant expressions, written and read by functions, arrays and structs at global scope
const float PI = 3.14159265;
float angle = PI * 0.25;
vec3 accum;
int counter = 0;
float history[4];
struct Stats { float lo; float hi; } stats = Stats(1e9, -1e9);
void record(float v) {
    history[counter % 4] = v;
    counter++;
    stats.lo = min(stats.lo, v);
    stats.hi = max(stats.hi, v);
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 p = fragCoord / iResolution.xy;
    accum = vec3(0.0);
    for (int i = 0; i < 4; i++) {
        record(p.x * float(i));
        accum += vec3(cos(angle * float(i)));
    }
    fragColor = vec4(accum * 0.25, history[3] + stats.hi - stats.lo + float(counter) * 0.0);
}
