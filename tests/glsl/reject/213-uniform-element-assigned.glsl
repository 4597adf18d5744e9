// rule: 4.3.5 Uniform: uniforms are read-only, also an array element
// error: 'assign' : l-value required "iChannelTime" (can't modify a uniform)
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    iChannelTime[0] = 1.0;
    fragColor = vec4(iChannelTime[0]);
}
