// rule: 3.3 Preprocessor: the behaviour of #extension is require, enable, warn or disable
// error: '#extension' : behavior not supported: maybe
#extension GL_OES_standard_derivatives : maybe
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
