// rule: 3.3 Preprocessor: #extension NAME : require fails when the extension is not supported
// error: '#extension' : extension not supported: GL_RASTERD_nonexistent
#extension GL_RASTERD_nonexistent : require
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
