// exercises: 6.1 overload resolution by exact parameter types: arrays of different sizes, different struct types, scalar versus vector, int versus uint versus float, in versus out parameters never ambiguous
struct A { float v; };
struct B { float v; };
float pick(float x[2]) { return x[0]; }
float pick(float x[3]) { return x[2]; }
float pick(A a) { return a.v; }
float pick(B b) { return -b.v; }
float pick(float x) { return x; }
float pick(vec2 x) { return x.y; }
float pick(int x) { return float(x) * 2.0; }
float pick(uint x) { return float(x) * 3.0; }
float pick(mat2 m) { return m[1][1]; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float s = pick(float[2](1.0, 2.0)) + pick(float[3](1.0, 2.0, 3.0)) + pick(A(1.0)) + pick(B(1.0))
            + pick(1.0) + pick(vec2(1.0, 2.0)) + pick(1) + pick(1u) + pick(mat2(4.0));
    fragColor = vec4(s * 0.05);
}
