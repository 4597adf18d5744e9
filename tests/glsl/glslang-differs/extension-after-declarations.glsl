// rule: 3.3 Preprocessor: #extension must come before any non-preprocessor token; the prelude's declarations always precede the program
// glslang: accepts: glslang does not check the position; ANGLE (WebGL 2, what ShaderToy runs) rejects "extension directive must occur before any non-preprocessor tokens in ESSL3". rasterd rejects
#extension GL_OES_standard_derivatives : enable
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(fwidth(fragCoord.x));
}
