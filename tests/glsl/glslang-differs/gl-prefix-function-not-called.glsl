// rule: 3.7 Identifiers: identifiers starting with gl_ are reserved and may not be declared as a variable or a function
// glslang: accepts: glslang reports the reserved name only where the function is called (see reject/ident-gl-prefix-function-called). rasterd rejects
float gl_twice(float x) { return 2.0 * x; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
