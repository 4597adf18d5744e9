// rule: 7.1 Vertex Shader Special Variables: gl_VertexID exists only in vertex shaders
// error: 'gl_VertexID' : undeclared identifier
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(float(gl_VertexID));
}
