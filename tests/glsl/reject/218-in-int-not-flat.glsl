// rule: 4.3.4 Input Variables: an integer fragment input must be qualified flat
// error: 'int' : must be qualified as flat in
in int id;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(float(id));
}
