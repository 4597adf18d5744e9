// rule: 8.3 Common Functions: modf's second argument is out and must be an l-value
// error: 'assign' : l-value required (can't modify a const)
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float whole;
    float f = modf(1.5, 1.0);
    fragColor = vec4(f);
}
