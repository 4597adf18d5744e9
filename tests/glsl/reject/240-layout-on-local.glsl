// rule: 4.3.8 Layout Qualifiers: layout qualifiers are for global inputs, outputs and uniform blocks
// error: 'location' : can only apply to uniform, buffer, in, or out storage qualifiers
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    layout(location = 0) float x = 1.0;
    fragColor = vec4(x);
}
