// rule: 7.3 Built-In Constants: built-in constants are const
// error: 'assign' : l-value required (can't modify a const)
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    int n;
    gl_MaxDrawBuffers = 2;
    fragColor = vec4(1.0);
}
