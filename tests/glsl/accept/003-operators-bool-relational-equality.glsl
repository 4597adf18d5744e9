// exercises: 5.1 && || ^^ ! on bool, < > <= >= on int/uint/float scalars, == != on scalars, vectors, matrices, structs and arrays, ?: on scalars, vectors and structs, the comma operator
struct Pair { float a; ivec2 b; };
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 p = fragCoord / iResolution.xy;
    bool a = p.x < 0.5, b = p.y >= 0.25;
    bool c = (a && b) || (!a ^^ b);
    bool d = iFrame > 3 && uint(iFrame) <= 10u && iTime != 0.0 && iTime == iTime;
    bool e = vec3(p, 1.0) == vec3(p, 1.0) && ivec2(1) != ivec2(2) && uvec4(1u) == uvec4(1u)
          && bvec2(a, b) != bvec2(b, a) && mat2(1.0) == mat2(1.0) && mat3x2(p.x) != mat3x2(p.y);
    Pair x = Pair(p.x, ivec2(1, 2)), y = Pair(p.y, ivec2(1, 2));
    float arr1[2] = float[2](p.x, p.y), arr2[2] = float[2](p.y, p.x);
    bool f = x == y || x != y || arr1 == arr2 || arr1 != arr2;
    Pair z = c ? x : y;
    vec3 v = e ? vec3(1.0) : vec3(0.0);
    int k = f ? 1 : (a ? 2 : 3);
    float seq = (k += 1, float(k) * 0.5);
    bool g = (a == b) != (c == d);
    fragColor = vec4(z.a + v.x + seq, g ? 1.0 : 0.0, float(z.b.y), 1.0);
}
