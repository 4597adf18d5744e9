// rule: 3.7 Identifiers: identifiers starting with gl_ are reserved; a variable cannot use them
// error: 'gl_scale' : identifiers starting with "gl_" are reserved
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float gl_scale = 1.0;
    fragColor = vec4(gl_scale);
}
