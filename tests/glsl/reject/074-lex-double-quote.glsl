// rule: 3.1 Character Set: there are no strings; `"` is not in the character set
// error: 'string literal' : required extension not requested: Possible extensions include:
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float x = 1.0;
    "label";
    fragColor = vec4(x);
}
