// rule: 3.6 Keywords: `sizeof` is reserved for future use; using it is an error
// error: 'sizeof' : Reserved word.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float sizeof = 1.0;
    fragColor = vec4(sizeof);
}
