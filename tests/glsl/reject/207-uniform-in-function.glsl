// rule: 4.3 Storage Qualifiers: uniform variables are declared at global scope only
// error: 'uniform' : not allowed in nested scope
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    uniform float u;
    fragColor = vec4(u);
}
