// rule: 3.3 Preprocessor: a redefinition must have the same whitespace separation (C++ rules)
// error: '#define' : Macro redefined; different substitutions: VALUE
#define VALUE (1.0 - 0.5)
#define VALUE (1.0- 0.5)
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(VALUE);
}
