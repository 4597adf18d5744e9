// rule: 4.1.7 Sampler Types: samplers can only be uniforms or function parameters
// error: 'sampler2D' : sampler/image types can only be used in uniform variables or function parameters: s
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    sampler2D s;
    fragColor = vec4(1.0);
}
