// exercises: 5.1 ?: with struct, vector and matrix results, nested; the sequence operator in expressions, in for headers and with void function calls
struct S { float v; };
void touch() { }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 p = fragCoord / iResolution.xy;
    bool c = p.x > 0.5;
    S s = c ? S(1.0) : S(0.0);
    vec2 a = c ? vec2(1.0, 2.0) : vec2(3.0, 4.0);
    mat2 m = c ? mat2(1.0) : mat2(2.0);
    float n = p.y < 0.3 ? 0.0 : p.y < 0.6 ? 0.5 : 1.0;
    float x = (touch(), 0.5);
    float y = 0.0;
    for (int i = 0, j = 10; i < j; i++, j--) y += 0.01;
    float z = (y += 1.0, y * 2.0);
    fragColor = vec4(s.v, a[1] + m[1][1], n + x, z * 0.1);
}
