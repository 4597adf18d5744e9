// rule: 4.1.7 Sampler Types: a global sampler must be a uniform
// error: 'sampler2D' : sampler/image types can only be used in uniform variables or function parameters: extra
sampler2D extra;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
