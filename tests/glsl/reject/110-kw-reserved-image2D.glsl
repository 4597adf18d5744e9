// rule: 3.6 Keywords: `image2D` is reserved for future use; using it is an error
// error: 'image2D' : Reserved word.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float image2D = 1.0;
    fragColor = vec4(image2D);
}
