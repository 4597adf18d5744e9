// rule: 3.6 Keywords: `sampler1D` is reserved for future use; using it is an error
// error: 'sampler1D' : Reserved word.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float sampler1D = 1.0;
    fragColor = vec4(sampler1D);
}
