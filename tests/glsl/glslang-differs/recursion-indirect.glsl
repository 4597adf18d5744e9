// rule: 6.1 Function Definitions: recursion is not allowed, not even statically (a cycle through two functions)
// glslang: accepts: -S does not link; `glslangValidator -l` reports "Recursion detected". rasterd rejects
float odd(int n);
float even(int n) { return n == 0 ? 1.0 : odd(n - 1); }
float odd(int n) { return n == 0 ? 0.0 : even(n - 1); }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(even(4));
}
