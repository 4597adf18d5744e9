// exercises: 5.10 products between non-square matrices and vectors of every compatible shape
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 v2 = fragCoord / iResolution.xy;
    vec3 v3 = vec3(v2, 1.0);
    vec4 v4 = vec4(v3, 1.0);
    mat2x3 a = mat2x3(1.0); mat3x2 b = mat3x2(1.0);
    mat2x4 c = mat2x4(1.0); mat4x2 d = mat4x2(1.0);
    mat3x4 e = mat3x4(1.0); mat4x3 f = mat4x3(1.0);
    vec3 r1 = a * v2; vec2 r2 = v3 * a;
    vec2 r3 = b * v3; vec3 r4 = v2 * b;
    vec4 r5 = c * v2; vec2 r6 = v4 * c;
    vec2 r7 = d * v4; vec4 r8 = v2 * d;
    vec4 r9 = e * v3; vec3 r10 = v4 * e;
    vec3 r11 = f * v4; vec4 r12 = v3 * f;
    mat3 p1 = a * b; mat2 p2 = b * a;
    mat4 p3 = c * d; mat2 p4 = d * c;
    mat4 p5 = e * f; mat3 p6 = f * e;
    mat3x4 p7 = c * b; mat4x3 p8 = a * d;
    float s = r1.x + r2.y + r3.x + r4.z + r5.w + r6.x + r7.y + r8.z + r9.w + r10.x + r11.y + r12.w
            + p1[2][2] + p2[1][1] + p3[3][3] + p4[0][0] + p5[2][1] + p6[1][2] + p7[2][3] + p8[3][2];
    fragColor = vec4(fract(s));
}
