// rule: 3.3 Preprocessor: #version must be the first thing in the shader; the prelude already has it, so a program cannot repeat it
// error: '#version' : must occur first in shader
#version 300 es
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
