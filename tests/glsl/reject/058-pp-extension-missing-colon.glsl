// rule: 3.3 Preprocessor: #extension NAME : BEHAVIOUR needs the colon
// error: '#extension' : ':' missing after extension name
#extension GL_OES_standard_derivatives enable
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
