// rule: 4.3 Storage Qualifiers: at most one storage qualifier
// error: 'const' : too many storage qualifiers
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    const const float x = 1.0;
    fragColor = vec4(x);
}
