// rule: 4.2 Scoping: a function cannot have the name of a struct type
// error: 'Hit' : function name is redeclaration of existing name
struct Hit { float t; };
float Hit(float t) { return t; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
