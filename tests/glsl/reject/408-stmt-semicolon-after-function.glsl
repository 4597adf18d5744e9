// rule: 9 Shading Language Grammar: a function definition is not followed by `;`
// error: 'extraneous semicolon' : not supported with this profile: es
float one() { return 1.0; };
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(one());
}
