// rule: 3.3 Preprocessor: GL_ES is predefined and cannot be redefined
// error: '#define' : names beginning with "GL_" can't be (un)defined: GL_ES
#define GL_ES 1
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
