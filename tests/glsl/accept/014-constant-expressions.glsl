// exercises: 4.3.3 constant expressions: const scalars, vectors, matrices, arrays and structs; built-in functions with constant arguments; constructors, swizzles, indexing, .length() and ?: in constant expressions; const ints as array sizes and case labels
const float PI = 3.14159265;
const float TAU = 2.0 * PI;
const vec3 UP = vec3(0.0, 1.0, 0.0);
const vec2 DIAG = normalize(vec2(1.0)) * sqrt(2.0);
const mat2 ROT = mat2(cos(0.5), sin(0.5), -sin(0.5), cos(0.5));
const float WEIGHTS[3] = float[3](0.25, 0.5, 0.25);
const int COUNT = WEIGHTS.length();
const int HALF = COUNT / 2;
const struct Cfg { int steps; float eps; } CFG = Cfg(64, 1e-3);
const float CLAMPED = clamp(pow(2.0, 3.0), 0.0, 5.0) + max(abs(-1.0), 0.5) + mod(7.0, 3.0) + step(0.5, 0.7);
const float PICK = COUNT > 2 ? WEIGHTS[HALF] : 0.0;
const float SW = UP.yx.x + DIAG.y + ROT[1][0];
const int SHIFTED = (1 << 4) | (0xF0 >> 2) & ~1;
const uint UBITS = 0xFFu ^ 0x0Fu;
const bool FLAG = all(lessThan(vec2(0.0), vec2(1.0))) && !any(bvec2(false));
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float acc[COUNT + 1];
    acc[COUNT] = TAU + CLAMPED + PICK + SW + float(SHIFTED) + float(UBITS) + float(CFG.steps) * CFG.eps;
    const float LOCAL = dot(UP, vec3(1.0)) * length(vec2(3.0, 4.0));
    switch (iFrame % 4) {
        case HALF: acc[0] = LOCAL; break;
        case COUNT: acc[0] = 2.0; break;
        case -1: acc[0] = 3.0; break;
        default: acc[0] = FLAG ? 1.0 : 0.0;
    }
    fragColor = vec4(fract(acc[COUNT]), acc[0], 0.0, 1.0);
}
