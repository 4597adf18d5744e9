// rule: 3.3 Preprocessor: a macro may be redefined only with the same replacement list
// error: '#define' : Macro redefined; different substitutions: SCALE
#define SCALE 1.0
#define SCALE 2.0
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(SCALE);
}
