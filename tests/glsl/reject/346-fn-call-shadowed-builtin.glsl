// rule: 4.2 Scoping: a local variable named dot hides the built-in function
// error: 'dot' : can't use function syntax on variable
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float dot = 1.0;
    fragColor = vec4(dot(vec2(1.0), vec2(1.0)) * dot);
}
