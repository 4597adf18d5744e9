// rule: 6.2 Selection: a switch body is a braced list
// error: '' : syntax error, unexpected CASE, expecting LEFT_BRACE
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(0.0);
    switch (iFrame) case 1: fragColor = vec4(1.0);
}
