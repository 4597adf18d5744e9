// rule: 8.8 Texture Lookup Functions: a constant offset must lie in [gl_MinProgramTexelOffset, gl_MaxProgramTexelOffset]
// error: 'texel offset' : value is out of range: [gl_MinProgramTexelOffset, gl_MaxProgramTexelOffset]
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = textureOffset(iChannel0, vec2(0.5), ivec2(100, 0));
}
