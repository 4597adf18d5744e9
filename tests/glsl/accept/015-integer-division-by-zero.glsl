// exercises: 5.9: integer division and modulo by zero are undefined results, not compile-time errors (glslang accepts them, also in constant expressions)
const int Z = 0;
const int Q = 7 / Z;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    int zero = 0;
    int a = 5 / zero;
    int b = 5 % zero;
    int c = 3 / 0;
    uint d = 9u / 0u;
    float e = 1.0 / 0.0;
    fragColor = vec4(float(a + b + c + Q) * 0.0, float(d) * 0.0, min(e, 1.0), 1.0);
}
