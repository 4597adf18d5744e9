// rule: 3.6 Keywords: `fixed` is reserved for future use; using it is an error
// error: 'fixed' : Reserved word.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float fixed = 1.0;
    fragColor = vec4(fixed);
}
