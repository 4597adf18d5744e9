// rule: 6.1 Function Definitions: a function that is called must be defined (prototype only here)
// glslang: accepts: -S does not link; `glslangValidator -l` reports "No function definition (body) found". rasterd rejects
float shade(vec2 p);
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(shade(fragCoord));
}
