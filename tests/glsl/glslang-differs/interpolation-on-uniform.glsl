// rule: 4.3 Storage Qualifiers: interpolation qualifiers may only precede in, centroid in, out or centroid out (not uniform, const or nothing)
// glslang: accepts: glslang takes smooth and flat before any storage qualifier, or none, at global scope. rasterd rejects
smooth uniform float gain;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(gain);
}
