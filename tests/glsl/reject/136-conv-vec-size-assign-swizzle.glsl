// rule: 5.8 Assignments: the value assigned must have the type of the l-value (vec3 to .xy)
// error: 'assign' : cannot convert from ' const 3-component vector of float' to ' temp highp 2-component vector of f...
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec4 c = vec4(0.0);
    c.xy = vec3(1.0);
    fragColor = c;
}
