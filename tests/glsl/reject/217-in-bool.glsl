// rule: 4.3.4 Input Variables: a fragment input cannot be a bool
// error: 'in' : cannot be bool
in bool lit;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
