// rule: 4.3.5 Uniform: uniforms are read-only
// error: 'assign' : l-value required "iTime" (can't modify a uniform)
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    iTime = 0.0;
    fragColor = vec4(iTime);
}
