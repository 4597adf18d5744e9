// rule: 4.1.5 Vectors: a vec2 cannot initialise a vec3 (no implicit size change)
// error: '=' : cannot convert from ' const 2-component vector of float' to ' temp highp 3-component vector of float'
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec3 v = vec2(1.0);
    fragColor = vec4(v, 1.0);
}
