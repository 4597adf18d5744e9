// rule: 8.8 Texture Lookup Functions: texture2DLod does not exist in ES 3.00; use textureLod
// error: 'texture2DLod' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = texture2DLod(iChannel0, vec2(0.5), 0.0);
}
