// exercises: 8.6 matrixCompMult, outerProduct, transpose (all 9 matrix types), determinant, inverse
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 p = fragCoord / iResolution.xy;
    int n = iFrame % 7;
    uint m = uint(iFrame) % 5u;
    float s = 0.0;
    { mat2 r = matrixCompMult(mat2(p.x * 0.25), mat2(p.x * 0.5)); s += r[0][0]; }
    { mat2 r = transpose(mat2(p.x * 0.25)); s += r[0][0]; }
    { mat3 r = matrixCompMult(mat3(p.x * 0.25), mat3(p.x * 0.5)); s += r[0][0]; }
    { mat3 r = transpose(mat3(p.x * 0.25)); s += r[0][0]; }
    { mat4 r = matrixCompMult(mat4(p.x * 0.25), mat4(p.x * 0.5)); s += r[0][0]; }
    { mat4 r = transpose(mat4(p.x * 0.25)); s += r[0][0]; }
    { mat2x3 r = matrixCompMult(mat2x3(p.x * 0.25), mat2x3(p.x * 0.5)); s += r[0][0]; }
    { mat3x2 r = transpose(mat2x3(p.x * 0.25)); s += r[0][0]; }
    { mat2x4 r = matrixCompMult(mat2x4(p.x * 0.25), mat2x4(p.x * 0.5)); s += r[0][0]; }
    { mat4x2 r = transpose(mat2x4(p.x * 0.25)); s += r[0][0]; }
    { mat3x2 r = matrixCompMult(mat3x2(p.x * 0.25), mat3x2(p.x * 0.5)); s += r[0][0]; }
    { mat2x3 r = transpose(mat3x2(p.x * 0.25)); s += r[0][0]; }
    { mat3x4 r = matrixCompMult(mat3x4(p.x * 0.25), mat3x4(p.x * 0.5)); s += r[0][0]; }
    { mat4x3 r = transpose(mat3x4(p.x * 0.25)); s += r[0][0]; }
    { mat4x2 r = matrixCompMult(mat4x2(p.x * 0.25), mat4x2(p.x * 0.5)); s += r[0][0]; }
    { mat2x4 r = transpose(mat4x2(p.x * 0.25)); s += r[0][0]; }
    { mat4x3 r = matrixCompMult(mat4x3(p.x * 0.25), mat4x3(p.x * 0.5)); s += r[0][0]; }
    { mat3x4 r = transpose(mat4x3(p.x * 0.25)); s += r[0][0]; }
    { mat2 r = outerProduct(vec2(p.x * 0.25, p.y), vec2(p.x * 0.5, p.y)); s += r[0][0]; }
    { mat2x3 r = outerProduct(vec3(p, 0.25), vec2(p.x * 0.5, p.y)); s += r[0][0]; }
    { mat2x4 r = outerProduct(vec4(p.x, p.y, p.x + p.y, 0.25), vec2(p.x * 0.5, p.y)); s += r[0][0]; }
    { mat3x2 r = outerProduct(vec2(p.x * 0.25, p.y), vec3(p, 0.5)); s += r[0][0]; }
    { mat3 r = outerProduct(vec3(p, 0.25), vec3(p, 0.5)); s += r[0][0]; }
    { mat3x4 r = outerProduct(vec4(p.x, p.y, p.x + p.y, 0.25), vec3(p, 0.5)); s += r[0][0]; }
    { mat4x2 r = outerProduct(vec2(p.x * 0.25, p.y), vec4(p.x, p.y, p.x + p.y, 0.5)); s += r[0][0]; }
    { mat4x3 r = outerProduct(vec3(p, 0.25), vec4(p.x, p.y, p.x + p.y, 0.5)); s += r[0][0]; }
    { mat4 r = outerProduct(vec4(p.x, p.y, p.x + p.y, 0.25), vec4(p.x, p.y, p.x + p.y, 0.5)); s += r[0][0]; }
    { float r = determinant(mat2(p.x * 0.25)); s += r; }
    { mat2 r = inverse(mat2(p.x * 1.5)); s += r[0][0]; }
    { float r = determinant(mat3(p.x * 0.25)); s += r; }
    { mat3 r = inverse(mat3(p.x * 1.5)); s += r[0][0]; }
    { float r = determinant(mat4(p.x * 0.25)); s += r; }
    { mat4 r = inverse(mat4(p.x * 1.5)); s += r[0][0]; }
    fragColor = vec4(vec3(fract(s)), 1.0);
}
