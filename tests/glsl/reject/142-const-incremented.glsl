// rule: 4.3.2 Constant Qualifier: a const variable cannot be written (++)
// error: '++' : l-value required (can't modify a const)
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    const int n = 1;
    n++;
    fragColor = vec4(float(n));
}
