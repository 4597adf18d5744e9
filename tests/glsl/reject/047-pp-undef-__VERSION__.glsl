// rule: 3.3 Preprocessor: __VERSION__ is predefined and cannot be undefined
// error: '#undef' : predefined names can't be (un)defined: __VERSION__
#undef __VERSION__
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
