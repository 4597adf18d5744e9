// rule: 6.2 Selection: default labels appear only in a switch
// error: 'default' : cannot appear outside switch statement
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    default: fragColor = vec4(1.0);
}
