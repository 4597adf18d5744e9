// rule: 5.7 Structure and Array Operations: .length() applies to arrays only in ES 3.00 (not vectors)
// error: '.length() on vectors and matrices' : not supported with this profile: es
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec3 v = vec3(1.0);
    int n = v.length();
    fragColor = vec4(float(n));
}
