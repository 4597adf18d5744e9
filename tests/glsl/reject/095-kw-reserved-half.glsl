// rule: 3.6 Keywords: `half` is reserved for future use; using it is an error
// error: 'half' : Reserved word.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float half = 1.0;
    fragColor = vec4(half);
}
