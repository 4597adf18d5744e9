// rule: 6.1 Function Definitions: built-in functions cannot be redeclared in ES 3.00
// error: 'redefinition of built-in function' : not supported with this profile: es
vec4 texture(sampler2D s, vec2 p);
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = texture(iChannel0, vec2(0.5));
}
