// rule: 6.2 Selection: a switch has at most one default
// error: 'default' : duplicate label
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    switch (iFrame) {
        default: fragColor = vec4(1.0); break;
        default: fragColor = vec4(0.0); break;
    }
}
