// rule: 4.3 Storage Qualifiers: in variables are declared at global scope only
// error: 'in' : not allowed in nested scope
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    in vec2 uv;
    fragColor = vec4(uv, 0.0, 1.0);
}
