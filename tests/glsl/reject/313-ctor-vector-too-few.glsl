// rule: 5.4.2 Vector and Matrix Constructors: a vector constructor needs enough components
// error: 'constructor' : not enough data provided for construction
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec3 v = vec3(1.0, 2.0);
    fragColor = vec4(v, 1.0);
}
