// rule: 4.2 Scoping: a name can be declared only once in a scope
// error: 'x' : redefinition
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float x = 1.0;
    float x = 2.0;
    fragColor = vec4(x);
}
