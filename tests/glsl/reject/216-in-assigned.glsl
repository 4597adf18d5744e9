// rule: 4.3.4 Input Variables: fragment inputs are read-only
// error: 'assign' : l-value required "uv" (can't modify shader input)
in vec2 uv;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    uv = vec2(0.0);
    fragColor = vec4(uv, 0.0, 1.0);
}
