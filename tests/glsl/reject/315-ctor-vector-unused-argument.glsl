// rule: 5.4.2 Vector and Matrix Constructors: an argument left entirely unused is an error
// error: 'constructor' : too many arguments
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec3 v = vec3(vec4(1.0), 1.0);
    fragColor = vec4(v, 1.0);
}
