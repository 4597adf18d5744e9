// rule: 6.2 Selection: an if condition cannot declare a variable
// error: '' : syntax error, unexpected IDENTIFIER, expecting LEFT_PAREN
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(0.0);
    if (bool b = iTime > 1.0) fragColor = vec4(1.0);
}
