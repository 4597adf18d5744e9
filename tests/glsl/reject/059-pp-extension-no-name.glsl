// rule: 3.3 Preprocessor: #extension needs an extension name
// error: '#extension' : extension name expected
#extension : warn
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
