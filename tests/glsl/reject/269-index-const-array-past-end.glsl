// rule: 4.3.3 Constant Expressions: indexing a const array past its end
// error: '[' : array index out of range '3'
const float W[3] = float[3](0.25, 0.5, 0.25);
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(W[3]);
}
