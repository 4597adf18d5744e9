// rule: 8.8 Texture Lookup Functions: texelFetch takes integer coordinates
// error: 'texelFetch' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = texelFetch(iChannel0, fragCoord, 0);
}
