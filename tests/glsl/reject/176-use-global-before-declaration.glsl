// rule: 4.2 Scoping: a global is visible only after its declaration
// error: 'K' : undeclared identifier
float twice(float x) { return K * x; }
const float K = 2.0;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(twice(0.5));
}
