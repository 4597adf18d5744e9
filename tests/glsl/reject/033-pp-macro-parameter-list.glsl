// rule: 3.3 Preprocessor: macro parameters are separated by commas
// error: '#define' : missing parenthesis
#define ADD(a b) ((a) + (b))
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(ADD(1.0, 2.0));
}
