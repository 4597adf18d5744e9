// rule: 5.4.2 Vector and Matrix Constructors: too many arguments (an argument that is not used at all)
// error: 'constructor' : too many arguments
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec3 v = vec3(1.0, 2.0, 3.0, 4.0);
    fragColor = vec4(v, 1.0);
}
