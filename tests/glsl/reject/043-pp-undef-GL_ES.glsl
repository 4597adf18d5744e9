// rule: 3.3 Preprocessor: GL_ES is predefined and cannot be undefined
// error: '#undef' : names beginning with "GL_" can't be (un)defined: GL_ES
#undef GL_ES
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
