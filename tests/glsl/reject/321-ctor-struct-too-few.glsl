// rule: 5.4.3 Structure Constructors: one argument per member
// error: 'constructor' : Number of constructor parameters does not match the number of structure fields
struct Hit { float t; int id; };
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    Hit h = Hit(1.0);
    fragColor = vec4(h.t);
}
