// rule: 8.8 Texture Lookup Functions: the offset is an ivec2
// error: 'textureOffset' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = textureOffset(iChannel0, vec2(0.5), vec2(1.0));
}
