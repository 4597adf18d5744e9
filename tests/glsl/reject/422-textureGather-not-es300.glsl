// rule: 8.8 Texture Lookup Functions: textureGather is not in ES 3.00 (it is ES 3.10)
// error: 'textureGather(...)' : not supported for this version or the enabled extensions
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = textureGather(iChannel0, vec2(0.5));
}
