// rule: 4.1.9 Arrays: an array declared without size needs an initialiser
// error: '' : array size required
float weights[];
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(weights[1]);
}
