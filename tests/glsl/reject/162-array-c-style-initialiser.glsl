// rule: 4.1.9 Arrays: there are no {...} initialiser lists in ES 3.00
// error: '{ } style initializers' : not supported with this profile: es
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float a[3] = {1.0, 2.0, 3.0};
    fragColor = vec4(a[1]);
}
