// rule: 4.3.3 Constant Expressions: a built-in function call with constant arguments (other than texture functions) is a constant expression
// glslang: rejects: glslang does not fold floatBitsToInt/Uint, intBitsToFloat, uintBitsToFloat, pack*/unpack*
const int BITS = floatBitsToInt(1.0);
const uint HALF = packHalf2x16(vec2(1.0, 0.5));
const float BACK = uintBitsToFloat(0x3f800000u);
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(float(BITS & 1) + float(HALF & 1u) + BACK);
}
