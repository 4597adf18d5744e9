// rule: 4.3 Storage Qualifiers: at most one storage qualifier (uniform const)
// error: 'const' : too many storage qualifiers
uniform const float level;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(level);
}
