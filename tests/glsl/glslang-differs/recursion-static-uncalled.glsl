// rule: 6.1 Function Definitions: static recursion (a cycle in the call graph) is an error even if the function is never called
// glslang: accepts: -S does not link; `glslangValidator -l` reports "Recursion detected". rasterd rejects
float forever(float x) { return forever(x + 1.0); }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
