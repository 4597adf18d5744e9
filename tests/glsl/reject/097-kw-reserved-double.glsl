// rule: 3.6 Keywords: `double` is reserved for future use; using it is an error
// error: 'double' : Reserved word.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float double = 1.0;
    fragColor = vec4(double);
}
