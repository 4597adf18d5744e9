// rule: 6.1.1 Function Calling Conventions / 9 Grammar: a parameter has one of in, out and inout; `in out` is not `inout`
// glslang: accepts: glslang merges `in out` (and `out in`) into inout. rasterd rejects
void twice(in out float x) { x = 2.0 * x; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float v = 0.25;
    twice(v);
    fragColor = vec4(v);
}
