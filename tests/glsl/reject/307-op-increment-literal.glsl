// rule: 5.1 Operators: ++ needs an l-value
// error: '++' : l-value required (can't modify a const)
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float x = 1.0++;
    fragColor = vec4(x);
}
