// rule: 3.6 Keywords: `static` is reserved for future use; using it is an error
// error: 'static' : Reserved word.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float static = 1.0;
    fragColor = vec4(static);
}
