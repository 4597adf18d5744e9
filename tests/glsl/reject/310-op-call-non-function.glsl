// rule: 5.3 Function Calls: only functions can be called
// error: 'x' : can't use function syntax on variable
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float x = 1.0;
    float y = x(2.0);
    fragColor = vec4(y);
}
