// rule: 4.2 Scoping: built-in functions are in the global scope; a struct cannot take the name `dot`
// error: 'dot' : redefinition struct
struct dot { float a; };
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
