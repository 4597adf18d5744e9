// rule: 8.5 Geometric Functions: cross takes vec3
// error: 'cross' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec3 c = cross(vec2(1.0, 0.0), vec2(0.0, 1.0));
    fragColor = vec4(c, 1.0);
}
