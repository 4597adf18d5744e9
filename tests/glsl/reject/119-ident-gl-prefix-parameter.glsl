// rule: 3.7 Identifiers: identifiers starting with gl_ are reserved; a parameter cannot use them
// error: 'gl_x' : identifiers starting with "gl_" are reserved
float twice(float gl_x) { return 2.0 * gl_x; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(twice(0.5));
}
