// rule: 3.6 Keywords: `superp` is reserved for future use; using it is an error
// error: 'superp' : Reserved word.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float superp = 1.0;
    fragColor = vec4(superp);
}
