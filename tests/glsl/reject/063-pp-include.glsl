// rule: 3.3 Preprocessor: there is no #include
// error: '#include' : required extension not requested: GL_GOOGLE_include_directive
#include "common.glsl"
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
