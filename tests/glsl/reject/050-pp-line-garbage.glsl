// rule: 3.3 Preprocessor: #line takes an integer expression (and an optional source-string number)
// error: 'preprocessor evaluation' : undefined macro in expression not allowed in es profile here
#line here
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
