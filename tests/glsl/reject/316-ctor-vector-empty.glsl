// rule: 5.4.2 Vector and Matrix Constructors: a constructor needs arguments
// error: 'constructor' : not enough data provided for construction
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec3 v = vec3();
    fragColor = vec4(v, 1.0);
}
