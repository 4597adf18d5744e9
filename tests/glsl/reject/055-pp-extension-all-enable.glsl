// rule: 3.3 Preprocessor: `#extension all` only takes warn or disable
// error: '#extension' : extension 'all' cannot have 'require' or 'enable' behavior
#extension all : enable
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
