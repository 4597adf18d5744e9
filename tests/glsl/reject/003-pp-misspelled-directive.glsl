// rule: 3.3 Preprocessor: only the listed directives exist; `#defin` is not one
// error: '#' : invalid directive: defin
#defin AAA 1.0
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
