// rule: 4.6 Variance and the Invariant Qualifier: parameters cannot be invariant
// error: '' : cannot use invariant qualifier on a function parameter
float f(invariant float x) { return x; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(f(1.0));
}
