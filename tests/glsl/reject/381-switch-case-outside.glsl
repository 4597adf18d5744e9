// rule: 6.2 Selection: case labels appear only in a switch
// error: 'case' : cannot appear outside switch statement
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    case 1: fragColor = vec4(1.0);
}
