// rule: 3.3 Preprocessor: there is no ## (token pasting) operator in GLSL ES
// error: 'token pasting (##)' : not supported with this profile: es
#define CAT(a, b) a ## b
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float CAT(my, value) = 1.0;
    fragColor = vec4(value);
}
