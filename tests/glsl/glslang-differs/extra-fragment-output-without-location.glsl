// rule: 4.3.8 Layout Qualifiers: with more than one fragment output every output needs a location; the epilogue's rasterd_FragColor has none, so a program may not add an output
// glslang: accepts: -S does not link; `glslangValidator -l` reports "when more than one fragment shader output, all must have location qualifiers". rasterd rejects
layout(location = 1) out vec4 extra;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
    extra = vec4(0.0);
}
