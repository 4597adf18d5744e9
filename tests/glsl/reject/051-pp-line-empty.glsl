// rule: 3.3 Preprocessor: #line needs a line number
// error: '#line' : must by followed by an integral literal
#line
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
