// rule: 4.3.8 Layout Qualifiers: a layout qualifier must be one ES 3.00 defines
// error: 'std999' : unrecognized layout identifier, or qualifier requires assignment (e.g., binding = 4)
layout(std999) uniform Settings { float gain; };
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(gain);
}
