// rule: 6.1 Function Definitions: recursion is not allowed, not even statically
// glslang: accepts: -S does not link; `glslangValidator -l` reports "Recursion detected". rasterd rejects
float countdown(float x) {
    return x > 0.0 ? countdown(x - 1.0) : 0.0;
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(countdown(3.0));
}
