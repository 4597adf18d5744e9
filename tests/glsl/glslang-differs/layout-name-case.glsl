// rule: 4.3.8 Layout Qualifiers: the names in a layout qualifier are identifiers, and as other identifiers they are case sensitive (std140, not STD140)
// glslang: accepts: glslang lowercases layout names before it looks them up. rasterd rejects
layout(STD140) uniform Settings { float gain; };
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(gain);
}
