// rule: 4.1.7 Sampler Types: a sampler parameter cannot be out or inout
// error: 'sampler2D' : samplers and atomic_uints cannot be output parameters
vec4 look(out sampler2D s) { return texture(s, vec2(0.5)); }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = look(iChannel0);
}
