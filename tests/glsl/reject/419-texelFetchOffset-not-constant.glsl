// rule: 8.8 Texture Lookup Functions: the offset of texelFetchOffset must be a constant expression
// error: 'texel offset' : argument must be compile-time constant
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = texelFetchOffset(iChannel0, ivec2(fragCoord), 0, ivec2(iFrame));
}
