// rule: 3.3 Preprocessor: __FILE__ is predefined and cannot be redefined
// error: '#define' : predefined names can't be (un)defined: __FILE__
#define __FILE__ 1
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
