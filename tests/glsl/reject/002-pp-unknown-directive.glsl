// rule: 3.3 Preprocessor: only the listed directives exist; `#foo` is not one
// error: '#' : invalid directive: foo
#foo
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
