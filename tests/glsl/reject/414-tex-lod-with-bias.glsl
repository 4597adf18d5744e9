// rule: 8.8 Texture Lookup Functions: textureLod takes no bias argument
// error: 'textureLod' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = textureLod(iChannel0, vec2(0.5), 0.0, 1.0);
}
