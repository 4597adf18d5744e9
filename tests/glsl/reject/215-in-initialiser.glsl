// rule: 4.3.4 Input Variables: fragment inputs cannot be initialised
// error: 'in' : cannot initialize this type of qualifier
in vec2 uv = vec2(0.0);
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(uv, 0.0, 1.0);
}
