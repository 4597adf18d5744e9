// rule: 4.1.1 Void: void is only a function return type (or an empty parameter list)
// error: 'v' : illegal use of type 'void'
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    void v;
    fragColor = vec4(1.0);
}
