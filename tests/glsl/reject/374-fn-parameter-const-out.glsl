// rule: 4.4 Parameter Qualifiers: const can only be combined with in
// error: 'out' : too many storage qualifiers
void set(const out float x) { }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float v = 1.0;
    set(v);
    fragColor = vec4(v);
}
