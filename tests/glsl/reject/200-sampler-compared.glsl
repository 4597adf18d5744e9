// rule: 4.1.7 Sampler Types: samplers cannot be compared
// error: '==' : can't use with samplers or structs containing samplers
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    bool same = iChannel0 == iChannel1;
    fragColor = vec4(same ? 1.0 : 0.0);
}
