// rule: 4.1.7 Sampler Types: samplers cannot be assigned
// error: '=' : can't use with samplers or structs containing samplers
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    iChannel0 = iChannel1;
    fragColor = vec4(1.0);
}
