// rule: 3.6 Keywords: `dvec2` is reserved for future use; using it is an error
// error: 'dvec2' : Reserved word.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float dvec2 = 1.0;
    fragColor = vec4(dvec2);
}
