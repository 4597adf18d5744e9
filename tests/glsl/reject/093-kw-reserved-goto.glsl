// rule: 3.6 Keywords: `goto` is reserved for future use; using it is an error
// error: 'goto' : Reserved word.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float goto = 1.0;
    fragColor = vec4(goto);
}
