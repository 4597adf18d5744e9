// rule: 4.1.9 Arrays: an array declared without size needs an initialiser
// error: '' : array size required
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float a[];
    fragColor = vec4(1.0);
}
