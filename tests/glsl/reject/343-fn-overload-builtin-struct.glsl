// rule: 6.1 Function Definitions: built-in functions cannot be overloaded, even for a user type
// error: 'length' : function name is redeclaration of existing name
struct Complex { float re; float im; };
float length(Complex c) { return sqrt(c.re * c.re + c.im * c.im); }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(length(Complex(3.0, 4.0)));
}
