// rule: 3.3 Preprocessor: a function-like macro may be redefined only with the same parameters
// error: '#define' : Macro redefined; different argument names: F
#define F(a) (a)
#define F(b) (b)
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(F(1.0));
}
