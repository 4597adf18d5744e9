// rule: 4.3.5 Uniform: uniforms are read-only, also through a swizzle
// error: 'assign' : l-value required "iResolution" (can't modify a uniform)
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    iResolution.x = 1.0;
    fragColor = vec4(iResolution, 1.0);
}
