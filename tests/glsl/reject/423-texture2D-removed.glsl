// rule: 8.8 Texture Lookup Functions: texture2D (ES 1.00) does not exist in ES 3.00; use texture
// error: 'texture2D' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = texture2D(iChannel0, vec2(0.5));
}
