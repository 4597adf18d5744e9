// rule: 8.8 Texture Lookup Functions: the bias is a float
// error: 'texture' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = texture(iChannel0, vec2(0.5), 1);
}
