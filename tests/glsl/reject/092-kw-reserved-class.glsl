// rule: 3.6 Keywords: `class` is reserved for future use; using it is an error
// error: 'class' : Reserved word.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float class = 1.0;
    fragColor = vec4(class);
}
