// rule: 3.7 Identifiers: identifiers starting with gl_ are reserved; a function cannot use them
// error: 'gl_twice' : identifiers starting with "gl_" are reserved
float gl_twice(float x) { return 2.0 * x; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(gl_twice(0.5));
}
