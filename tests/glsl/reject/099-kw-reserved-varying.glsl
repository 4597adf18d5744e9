// rule: 3.6 Keywords: `varying` is reserved for future use; using it is an error
// error: 'varying' : Reserved word.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float varying = 1.0;
    fragColor = vec4(varying);
}
