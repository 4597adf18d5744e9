// rule: 3.3 Preprocessor: #else needs an open #if
// error: '#else' : mismatched statements
#else
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
