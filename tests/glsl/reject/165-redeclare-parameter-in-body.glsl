// rule: 4.2 Scoping: a function's parameters and its body's top level share one scope
// error: 'x' : redefinition
float f(float x) {
    float x = 2.0 * x;
    return x;
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(f(0.5));
}
