// rule: 8.8 Texture Lookup Functions: textureSize(sampler2D, lod) takes the lod
// error: 'textureSize' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 size = vec2(textureSize(iChannel0));
    fragColor = vec4(size, 0.0, 1.0);
}
