// rule: 3.3 Preprocessor: macro names beginning with GL_ are reserved; undefining one is an error
// error: '#undef' : names beginning with "GL_" can't be (un)defined: GL_QUALITY
#undef GL_QUALITY
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
