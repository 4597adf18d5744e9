// rule: 3.6 Keywords: there is no goto (it is reserved)
// error: 'goto' : Reserved word.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
    goto done;
}
