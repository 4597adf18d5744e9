// rule: 5.4.1 Conversion and Scalar Constructors: a scalar constructor takes one argument
// error: 'constructor' : too many arguments
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float f = float(1.0, 2.0);
    fragColor = vec4(f);
}
