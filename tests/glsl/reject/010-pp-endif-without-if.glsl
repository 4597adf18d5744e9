// rule: 3.3 Preprocessor: #endif needs an open #if
// error: '#endif' : mismatched statements
#endif
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
