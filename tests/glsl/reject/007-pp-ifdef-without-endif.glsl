// rule: 3.3 Preprocessor: every #ifdef needs its #endif
// error: '' : missing #endif
#ifdef GL_ES
precision mediump float;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
