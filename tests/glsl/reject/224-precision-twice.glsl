// rule: 4.5 Precision and Precision Qualifiers: at most one precision qualifier
// error: 'mediump' : only one precision qualifier allowed
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    highp mediump float x = 1.0;
    fragColor = vec4(x);
}
