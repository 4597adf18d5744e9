// rule: 8.8 Texture Lookup Functions: the offset of textureOffset must be a constant expression
// error: 'texel offset' : argument must be compile-time constant
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    ivec2 o = ivec2(iFrame % 2, 0);
    fragColor = textureOffset(iChannel0, vec2(0.5), o);
}
