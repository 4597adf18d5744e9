// rule: 4.1.7 Sampler Types: a function cannot return a sampler
// error: 'return' : sampler or image can be used as return type only when the extension GL_ARB_bindless_texture enabled
sampler2D pick() { return iChannel0; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
