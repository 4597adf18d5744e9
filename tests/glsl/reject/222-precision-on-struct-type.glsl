// rule: 4.5 Precision and Precision Qualifiers: a struct type takes no precision qualifier
// error: 'structure' : type cannot have precision qualifier
struct S { float a; };
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    highp S s = S(1.0);
    fragColor = vec4(s.a);
}
