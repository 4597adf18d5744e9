// rule: 7.2 Fragment Shader Special Variables: gl_FragData does not exist in ES 3.00
// error: 'gl_FragData' : undeclared identifier
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
    gl_FragData[0] = vec4(1.0);
}
