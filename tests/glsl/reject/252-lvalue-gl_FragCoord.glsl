// rule: 7.2 Fragment Shader Special Variables: gl_FragCoord is read-only
// error: 'assign' : l-value required "gl_FragCoord" (can't modify gl_FragCoord)
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec4 p = gl_FragCoord;
    gl_FragCoord.x = 1.0;
    fragColor = p;
}
