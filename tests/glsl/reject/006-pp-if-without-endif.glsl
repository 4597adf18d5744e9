// rule: 3.3 Preprocessor: every #if needs its #endif
// error: '' : missing #endif
#if 1
float half_of(float x) { return 0.5 * x; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(half_of(1.0));
}
