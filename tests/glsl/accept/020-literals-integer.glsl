// exercises: 4.1.3 integer literals: decimal, octal, hexadecimal (upper and lower case digits and prefix), u and U suffixes, 2147483648..4294967295 and 0xffffffff as int (bit pattern fits 32 bits), negated literals
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    int a = 0, b = 42, c = 017, d = 0x1F, e = 0XaBcD, f = -7;
    int g = 2147483647, h = -2147483648, i = 2147483648, j = 4294967295, k = 0xffffffff;
    uint u1 = 0u, u2 = 42U, u3 = 017u, u4 = 0x1Fu, u5 = 4294967295u, u6 = 0XFFFFFFFFU;
    int sum = a + b + c + d + e + f + (g & 1) + (h & 1) + (i & 1) + (j & 1) + (k & 1);
    uint usum = u1 + u2 + u3 + u4 + (u5 & 1u) + (u6 & 1u);
    fragColor = vec4(float(sum) * 0.0001, float(usum) * 0.001, 0.0, 1.0);
}
