// rule: 3.3 Preprocessor: there is no # (stringizing) operator: the `#` reaches the program
// error: '#' : preprocessor directive cannot be preceded by another token
#define NAME(x) #x
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float NAME(y) = 1.0;
    fragColor = vec4(y);
}
