// rule: 5.4.4 Array Constructors: an unsized array constructor needs at least one argument
// error: 'constructor' : array constructor must have at least one argument
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float a[1] = float[]();
    fragColor = vec4(a[0]);
}
