// rule: 3.6 Keywords: `output` is reserved for future use; using it is an error
// error: 'output' : Reserved word.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float output = 1.0;
    fragColor = vec4(output);
}
