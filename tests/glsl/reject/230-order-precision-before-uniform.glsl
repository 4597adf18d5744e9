// rule: 4.7 Order of Qualification: the precision qualifier comes after the storage qualifier
// error: '' : precision qualifier must appear as last qualifier
highp uniform float gain;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(gain);
}
