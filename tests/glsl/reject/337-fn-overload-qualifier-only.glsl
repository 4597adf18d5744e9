// rule: 6.1 Function Definitions: overloads cannot differ only in parameter qualifiers (in vs out)
// error: 'out' : overloaded functions must have the same parameter storage qualifiers for argument 1
void set(in float a) { }
void set(out float a) { a = 1.0; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    set(1.0);
    fragColor = vec4(1.0);
}
