// rule: 4.3 Storage Qualifiers: out variables are declared at global scope only
// error: 'out' : not allowed in nested scope
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    out vec4 c;
    fragColor = c;
}
