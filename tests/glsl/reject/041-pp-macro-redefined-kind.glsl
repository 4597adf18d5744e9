// rule: 3.3 Preprocessor: a function-like macro cannot be redefined as an object-like one
// error: '#define' : Macro redefined; function-like versus object-like: F
#define F(a) (a)
#define F 1.0
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
