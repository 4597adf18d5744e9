// rule: 3.3 Preprocessor: #error in a group that is taken makes the compilation fail
// error: '#error' : taken
#if 0
#elif 1
#error taken
#endif
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
