// rule: 4.3.2 Constant Qualifier: a const variable must be initialised
// error: 'TINT' : variables with qualifier 'const' must be initialized
const vec3 TINT;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
