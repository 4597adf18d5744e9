// rule: 3.6 Keywords: `input` is reserved for future use; using it is an error
// error: 'input' : Reserved word.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float input = 1.0;
    fragColor = vec4(input);
}
