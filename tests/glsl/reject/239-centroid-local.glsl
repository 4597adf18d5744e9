// rule: 4.3 Storage Qualifiers: centroid is for global inputs and outputs
// error: 'centroid' : not allowed in nested scope
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    centroid float x = 1.0;
    fragColor = vec4(x);
}
