// rule: 8.8 Texture Lookup Functions: the first argument of texture is a sampler
// error: 'texture' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = texture(iTime, vec2(0.5));
}
