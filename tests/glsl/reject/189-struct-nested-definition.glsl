// rule: 4.1.8 Structures: a struct definition cannot be nested in a struct
// error: '' : cannot nest a structure definition inside a structure or block
struct Outer { struct Inner { float a; } inner; };
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
