// rule: 3.6 Keywords: `namespace` is reserved for future use; using it is an error
// error: 'namespace' : Reserved word.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float namespace = 1.0;
    fragColor = vec4(namespace);
}
