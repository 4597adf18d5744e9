// exercises: 4.1.4 float literals: 1.  .5  1.5  1e3  1E-3  2.5e+2  1.5E-3f  2.0F  0.0  leading zeros (09.5), a huge exponent (1e50 overflows, no error)
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float a = 1., b = .5, c = 1.5, d = 1e3, e = 1E-3, f = 2.5e+2, g = 1.5E-3f, h = 2.0F, i = 0.0, j = 09.5, k = 00.25;
    float l = .5e1, m = 5.e-1, n = 1e0f;
    float huge = 1e50;
    fragColor = vec4(a + b + c + d * 0.001 + e + f * 0.001 + g + h + i + j + k + l + m + n, min(huge, 1.0), 0.0, 1.0) * 0.05;
}
