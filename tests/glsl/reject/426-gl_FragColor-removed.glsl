// rule: 7.2 Fragment Shader Special Variables: gl_FragColor does not exist in ES 3.00
// error: 'gl_FragColor' : undeclared identifier
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    gl_FragColor = vec4(1.0);
}
