// rule: 4.1.8 Structures: members cannot have storage qualifiers
// error: 'a' : cannot use storage or interpolation qualifiers on structure members
struct S { const float a; };
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
