// rule: 3.6 Keywords: `long` is reserved for future use; using it is an error
// error: 'long' : Reserved word.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float long = 1.0;
    fragColor = vec4(long);
}
