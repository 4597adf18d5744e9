// rule: 4.2 Scoping: a function cannot have the name of a global variable
// error: 'shade' : function name is redeclaration of existing name
float shade = 2.0;
float shade() { return 1.0; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(shade());
}
