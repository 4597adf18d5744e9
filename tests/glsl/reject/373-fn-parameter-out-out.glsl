// rule: 4.4 Parameter Qualifiers: at most one of in, out, inout
// error: 'out' : too many storage qualifiers
void set(out out float x) { x = 1.0; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float v;
    set(v);
    fragColor = vec4(v);
}
