// rule: 4.3.5 Uniform: uniforms are read-only (++)
// error: '++' : l-value required "iTime" (can't modify a uniform)
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    iTime++;
    fragColor = vec4(iTime);
}
