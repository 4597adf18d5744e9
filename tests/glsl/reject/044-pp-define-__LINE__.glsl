// rule: 3.3 Preprocessor: __LINE__ is predefined and cannot be redefined
// error: '#define' : predefined names can't be (un)defined: __LINE__
#define __LINE__ 10
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
