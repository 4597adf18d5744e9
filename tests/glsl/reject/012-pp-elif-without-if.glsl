// rule: 3.3 Preprocessor: #elif needs an open #if
// error: '#elif' : mismatched statements
#elif 1
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
