// rule: 3.7 Identifiers: identifiers starting with gl_ are reserved; a global variable cannot use them
// error: 'gl_Pi' : identifiers starting with "gl_" are reserved
const float gl_Pi = 3.14159;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(gl_Pi);
}
