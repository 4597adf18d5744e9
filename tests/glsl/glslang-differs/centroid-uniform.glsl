// rule: 4.3 Storage Qualifiers / 9 Grammar: centroid is part of the storage qualifiers `centroid in` and `centroid out`; `centroid uniform` is not one
// glslang: accepts: glslang takes centroid as an auxiliary qualifier beside any storage (its error for it is about interpolation, not uniforms). rasterd rejects
centroid uniform float level;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(level);
}
