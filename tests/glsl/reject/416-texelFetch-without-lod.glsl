// rule: 8.8 Texture Lookup Functions: texelFetch takes a lod argument
// error: 'texelFetch' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = texelFetch(iChannel0, ivec2(fragCoord));
}
