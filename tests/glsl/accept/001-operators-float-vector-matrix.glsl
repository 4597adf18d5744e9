// exercises: 5.1/5.10 arithmetic on float, vecN and matrices (linear-algebra *, component-wise + - /, scalar forms), unary -, ++/--, compound assignment
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 p = fragCoord / iResolution.xy;
    float f = p.x + p.y - p.x * p.y / (1.0 + p.x);
    f = -f;
    vec2 a = p + 1.0, b = 2.0 - p, c = p * 3.0, d = 4.0 / (p + 1.0);
    vec3 v = vec3(p, f) * vec3(2.0) / vec3(3.0) - vec3(1.0) + vec3(0.5);
    vec4 w = -vec4(a, b);
    mat2 m2 = mat2(p, p.yx);
    mat3 m3 = mat3(1.0) * 2.0;
    mat4 m4 = 0.5 * mat4(1.0);
    mat2x3 m23 = mat2x3(1.0);
    mat3x2 m32 = mat3x2(1.0);
    vec2 mv = m2 * p;
    vec2 vm = p * m2;
    vec3 r3 = m23 * p;
    vec2 r2 = m32 * v;
    vec3 l3 = p * m32;
    mat2 mm = m2 * m2 + m32 * m23;
    mat3 nn = m23 * m32 - m3 / 2.0;
    mat2x3 k = m3 * m23;
    mat4 q = m4 * m4 + m4 - m4 / 3.0;
    q = -q;
    vec4 t = q * w + w * q;
    f += 1.0; f -= 0.5; f *= 2.0; f /= 3.0;
    a += b; a -= c; a *= d; a /= 2.0; a *= m2; a += 1.0;
    m2 *= m2; m2 += 1.0; m2 -= mat2(0.5); m2 /= 2.0; m2 *= 3.0;
    m3 *= nn;
    float i = 0.0;
    i++; ++i; i--; --i;
    float post = i++ + ++i;
    v++; --v;
    m4++; --m4;
    fragColor = vec4(f + post + mv.x + vm.y + r3.z + r2.x + l3.y + mm[1][1] + k[1][2] + m3[2][2], a, t.w + v.x + m2[0][0] + m4[3][3]);
}
