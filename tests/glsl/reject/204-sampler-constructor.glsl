// rule: 4.1.7 Sampler Types: samplers have no constructor
// error: 'sampler2D' : sampler-constructor requires the extension GL_ARB_bindless_texture enabled
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = texture(sampler2D(iChannel0), vec2(0.5));
}
