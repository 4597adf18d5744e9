// rule: 9 Shading Language Grammar: an empty declaration `;` at global scope is not in the ES grammar
// error: 'extraneous semicolon' : not supported with this profile: es
float g = 1.0;;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(g);
}
