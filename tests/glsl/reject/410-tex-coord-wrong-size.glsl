// rule: 8.8 Texture Lookup Functions: texture(sampler2D, P) takes a vec2 P
// error: 'texture' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = texture(iChannel0, vec3(0.5));
}
