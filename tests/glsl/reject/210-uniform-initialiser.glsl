// rule: 4.3.5 Uniform: uniforms cannot be initialised in the shader
// error: 'uniform' : cannot initialize this type of qualifier
uniform float speed = 1.0;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(speed);
}
