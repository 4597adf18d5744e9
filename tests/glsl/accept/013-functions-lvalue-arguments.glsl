// exercises: 6.1.1 out and inout arguments that are l-values: array elements, struct members, swizzles with distinct components (in any order), other out parameters; writing an in parameter (a local copy); chained assignment
struct State { vec3 pos; float t[2]; };
void setTwo(out vec2 v) { v = vec2(1.0, 2.0); }
void bump(inout float f) { f += 1.0; }
void forward(out vec2 v) { setTwo(v); }
float halve(in float x, vec2 y) {
    x *= 0.5;
    y.x = x;
    return x + y.x;
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec4 c = vec4(0.0);
    setTwo(c.wy);
    vec2 arr[3];
    setTwo(arr[2]);
    State s;
    s.t[1] = 0.0;
    bump(s.t[1]);
    setTwo(s.pos.zx);
    bump(c.x);
    forward(arr[0]);
    float a, b, d;
    a = b = d = 0.5;
    a = halve(a, vec2(b));
    fragColor = c + vec4(arr[2], arr[0]) * 0.1 + vec4(s.pos, s.t[1]) * (a + b + d);
}
