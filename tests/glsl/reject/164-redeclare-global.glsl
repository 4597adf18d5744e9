// rule: 4.2 Scoping: a name can be declared only once in a scope
// error: 'g' : redefinition
float g = 1.0;
float g = 2.0;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(g);
}
