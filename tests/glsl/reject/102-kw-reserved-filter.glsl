// rule: 3.6 Keywords: `filter` is reserved for future use; using it is an error
// error: 'filter' : Reserved word.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float filter = 1.0;
    fragColor = vec4(filter);
}
