// rule: 4.1.7 Sampler Types: in ES 3.00 an array of samplers can only be indexed by a constant expression
// error: 'variable indexing sampler array' : not supported for this version or the enabled extensions
uniform sampler2D layers[2];
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = texture(layers[iFrame], vec2(0.5));
}
