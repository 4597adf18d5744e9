// rule: 4.7 Order of Qualification / 9 Grammar: in ES 3.00 a layout qualifier precedes the storage qualifier (`layout(...) uniform`)
// glslang: accepts: glslang accepts qualifiers in any order relative to layout (ES 3.10 relaxed this). rasterd rejects
uniform layout(std140) Settings { float gain; };
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(gain);
}
