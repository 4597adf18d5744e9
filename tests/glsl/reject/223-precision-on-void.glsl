// rule: 4.5 Precision and Precision Qualifiers: void takes no precision qualifier
// error: 'void' : type cannot have precision qualifier
highp void paint(out vec4 c) { c = vec4(1.0); }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    paint(fragColor);
}
