// rule: 4.3.3 Constant Expressions: a built-in function call with constant arguments (other than texture functions) is a constant expression
// glslang: rejects: glslang does not fold sinh, cosh, tanh, asinh, acosh, atanh ("global const initializers must be constant" / "non-constant initializer")
const float K = sinh(1.0) + cosh(1.0) + tanh(1.0) + asinh(1.0) + acosh(1.5) + atanh(0.5);
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(K * 0.1);
}
