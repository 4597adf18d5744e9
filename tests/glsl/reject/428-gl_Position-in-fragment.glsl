// rule: 7.1 Vertex Shader Special Variables: gl_Position exists only in vertex shaders
// error: 'gl_Position' : undeclared identifier
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
    gl_Position = vec4(0.0);
}
