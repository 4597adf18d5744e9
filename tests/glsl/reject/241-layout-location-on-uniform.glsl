// rule: 4.3.8 Layout Qualifiers: ES 3.00 has no location for uniforms
// error: 'location qualifier on uniform or buffer' : not supported for this version or the enabled extensions
layout(location = 0) uniform float gain;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(gain);
}
