// rule: 5.4.3 Structure Constructors: members are not filled from vector components
// error: 'constructor' : Number of constructor parameters does not match the number of structure fields
struct Pair { float a; float b; };
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    Pair p = Pair(vec2(1.0, 2.0));
    fragColor = vec4(p.a + p.b);
}
