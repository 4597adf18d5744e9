// rule: 3.6 Keywords: `attribute` is reserved for future use; using it is an error
// error: 'attribute' : Reserved word.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float attribute = 1.0;
    fragColor = vec4(attribute);
}
