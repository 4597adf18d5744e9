// rule: 3.3 Preprocessor: #line takes at most a line and a source-string number
// error: '#line' : unexpected tokens following directive
#line 10 1 2
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
