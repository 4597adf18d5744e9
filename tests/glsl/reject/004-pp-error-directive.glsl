// rule: 3.3 Preprocessor: #error makes the compilation fail
// error: '#error' : this program is not finished
#error this program is not finished
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
