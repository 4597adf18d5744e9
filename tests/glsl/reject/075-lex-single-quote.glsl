// rule: 3.1 Character Set: there are no character literals
// error: ''' : character literals not supported
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    int c = 'a';
    fragColor = vec4(float(c));
}
