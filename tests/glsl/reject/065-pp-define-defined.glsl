// rule: 3.3 Preprocessor: `defined` cannot be a macro name (undefined in C++; WebGL 2 requires an error)
// error: '#define' : "defined" can't be (un)defined: defined
#define defined 1
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
