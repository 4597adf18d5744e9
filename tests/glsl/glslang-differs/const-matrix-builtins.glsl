// rule: 4.3.3 Constant Expressions: a built-in function call with constant arguments (other than texture functions) is a constant expression
// glslang: rejects: glslang does not fold transpose, inverse, determinant, matrixCompMult
const mat2 M = transpose(mat2(1.0, 2.0, 3.0, 4.0)) + inverse(mat2(2.0)) + matrixCompMult(mat2(1.0), mat2(2.0));
const float DET = determinant(mat3(2.0));
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(M[0], M[1] * DET);
}
