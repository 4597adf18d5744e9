// rule: 4.5 Precision and Precision Qualifiers: bool takes no precision qualifier
// error: 'bool' : type cannot have precision qualifier
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    highp bool b = true;
    fragColor = vec4(b ? 1.0 : 0.0);
}
