// rule: 8.5 Geometric Functions: refract's eta is a float
// error: 'refract' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec3 r = refract(vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0), vec3(1.5));
    fragColor = vec4(r, 1.0);
}
