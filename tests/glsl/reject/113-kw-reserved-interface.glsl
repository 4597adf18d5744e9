// rule: 3.6 Keywords: `interface` is reserved for future use; using it is an error
// error: 'interface' : Reserved word.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float interface = 1.0;
    fragColor = vec4(interface);
}
