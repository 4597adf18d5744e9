// rule: 3.6 Keywords: `shared` is not a keyword or reserved word of ES 3.00 (it is a keyword of ES 3.10), so it is an ordinary name
// glslang: rejects: glslang lexes `shared` as a keyword in ES 3.00 too ("syntax error, unexpected SHARED")
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float shared = 0.5;
    fragColor = vec4(shared);
}
