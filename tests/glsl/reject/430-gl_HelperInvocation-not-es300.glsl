// rule: 7.2 Fragment Shader Special Variables: gl_HelperInvocation is not in ES 3.00
// error: 'gl_HelperInvocation' : undeclared identifier
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(gl_HelperInvocation ? 1.0 : 0.0);
}
