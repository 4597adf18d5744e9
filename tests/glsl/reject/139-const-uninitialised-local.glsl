// rule: 4.3.2 Constant Qualifier: a const variable must be initialised
// error: 'x' : variables with qualifier 'const' must be initialized
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    const float x;
    fragColor = vec4(1.0);
}
