// rule: 3.3 Preprocessor: macro names beginning with GL_ are reserved; defining one is an error
// error: '#define' : names beginning with "GL_" can't be (un)defined: GL_QUALITY
#define GL_QUALITY 2
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
