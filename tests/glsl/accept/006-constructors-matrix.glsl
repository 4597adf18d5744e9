// exercises: 5.4.2 matrix constructors: one scalar (diagonal), column vectors, all components, a vec4 into a mat2, mixed scalars and vectors, from a larger and a smaller matrix, every non-square type
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 p = fragCoord / iResolution.xy;
    mat2 a = mat2(2.0);
    mat2 b = mat2(p, p.yx);
    mat2 c = mat2(1.0, 2.0, 3.0, 4.0);
    mat2 d = mat2(vec4(p, p));
    mat2 e = mat2(p.x, vec2(1.0, 2.0), p.y);
    mat3 f = mat3(vec3(1.0), vec3(p, 0.0), vec3(0.0, 0.0, 1.0));
    mat3 g = mat3(1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0);
    mat4 h = mat4(vec4(1.0), vec4(2.0), vec4(3.0), vec4(4.0));
    mat4 i = mat4(1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0, 11.0, 12.0, 13.0, 14.0, 15.0, 16.0);
    mat3 j = mat3(h);
    mat2 k = mat2(f);
    mat4 l = mat4(b);
    mat3 m = mat3(a);
    mat2x3 n = mat2x3(vec3(1.0), vec3(2.0));
    mat2x4 o = mat2x4(1.0);
    mat3x2 q = mat3x2(p, p, p);
    mat3x4 r = mat3x4(h);
    mat4x2 s = mat4x2(1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0);
    mat4x3 t = mat4x3(f);
    mat2x2 u = mat2x2(q);
    mat3x3 v = mat3x3(n);
    mat4x4 w = mat4x4(t);
    mat3 x = mat3(vec2(1.0), 2.0, vec4(3.0), vec2(4.0));
    float sum = a[0][0] + b[1][0] + c[1][1] + d[0][1] + e[1][1] + f[1][0] + g[2][2] + h[3][3] + i[2][1]
              + j[1][1] + k[0][0] + l[3][3] + m[2][2] + n[1][2] + o[1][3] + q[2][1] + r[2][3] + s[3][1]
              + t[3][2] + u[1][1] + v[2][2] + w[3][3] + x[2][1];
    fragColor = vec4(fract(sum * 0.01));
}
