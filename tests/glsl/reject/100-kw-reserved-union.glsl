// rule: 3.6 Keywords: `union` is reserved for future use; using it is an error
// error: 'union' : Reserved word.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float union = 1.0;
    fragColor = vec4(union);
}
