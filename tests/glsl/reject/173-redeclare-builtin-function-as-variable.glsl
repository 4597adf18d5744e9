// rule: 4.2 Scoping: built-in functions are in the global scope; a global cannot take the name `sin`
// error: 'sin' : redefinition
float sin = 1.0;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(sin);
}
