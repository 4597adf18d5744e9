// exercises: uint values everywhere: literals, conversions, wrap-around, shifts by int and uint, comparisons, uvec component-wise operations, unsigned loop counters
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    uint seed = uint(fragCoord.x) * 1973u + uint(fragCoord.y) * 9277u + uint(iFrame) * 26699u;
    seed = (seed ^ 61u) ^ (seed >> 16u);
    seed *= 9u;
    seed = seed ^ (seed >> 4);
    seed *= 0x27d4eb2du;
    seed = seed ^ (seed >> 15);
    uint wrapped = 0u - 1u;
    bool big = wrapped > 0x7fffffffu && seed >= 0u;
    uvec3 v = uvec3(seed, seed >> 8, seed >> 16) & uvec3(255u);
    uint count = 0u;
    for (uint i = 0u; i < 32u; ++i) count += (seed >> i) & 1u;
    fragColor = vec4(vec3(v) / 255.0, big ? float(count) / 32.0 : 0.0);
}
