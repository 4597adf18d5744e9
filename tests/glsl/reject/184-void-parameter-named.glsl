// rule: 4.1.1 Void: a parameter cannot have type void
// error: 'x' : illegal use of type 'void'
float f(void x) { return 1.0; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(f());
}
