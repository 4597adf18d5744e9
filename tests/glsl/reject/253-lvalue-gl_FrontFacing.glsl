// rule: 7.2 Fragment Shader Special Variables: gl_FrontFacing is read-only
// error: 'assign' : l-value required "gl_FrontFacing" (can't modify gl_FrontFace)
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    bool f;
    gl_FrontFacing = true;
    fragColor = vec4(1.0);
}
