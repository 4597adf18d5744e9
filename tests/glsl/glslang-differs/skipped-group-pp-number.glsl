// rule: 3.3 Preprocessor: text in a skipped #if group is only scanned for directives; `08` is a valid preprocessing number there
// glslang: rejects: glslang's scanner validates numbers in skipped groups ("octal literal digit too large"; also 1e, 0x, 4294967296, an unmatched quote)
#if 0
const int MONTH = 08;
#endif
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
