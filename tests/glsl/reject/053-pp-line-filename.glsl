// rule: 3.3 Preprocessor: #line takes numbers; a file name in quotes is not ES 3.00
// error: 'filename-based #line' : required extension not requested: GL_GOOGLE_cpp_style_line_directive
#line 10 "helpers.glsl"
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
