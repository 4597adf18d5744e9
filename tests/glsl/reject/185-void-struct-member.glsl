// rule: 4.1.8 Structures: a member cannot have type void
// error: 'b' : illegal use of type 'void'
struct S { float a; void b; };
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
