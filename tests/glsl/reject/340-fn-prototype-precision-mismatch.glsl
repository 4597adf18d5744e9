// rule: 6.1 Function Definitions: a prototype and its definition must have the same parameter precisions
// error: 'highp' : overloaded functions must have the same parameter precision qualifiers for argument 1
float f(mediump float a);
float f(highp float a) { return a; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(f(1.0));
}
