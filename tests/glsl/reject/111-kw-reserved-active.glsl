// rule: 3.6 Keywords: `active` is reserved for future use; using it is an error
// error: 'active' : Reserved word.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float active = 1.0;
    fragColor = vec4(active);
}
