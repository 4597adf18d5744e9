// exercises: 6.2 switch: on int and uint, fall-through, default in the middle, several labels on one statement, negative and constant-expression labels, declarations directly in a case, nested switch, break inside a loop inside a case, continue in a switch inside a loop, an empty switch
const int RED = 1;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec3 c = vec3(0.0);
    int mode = iFrame % 6 - 1;
    switch (mode) {
        case -1:
            c.r = 0.5;
        case RED:
        case RED + 1:
            c.g = 0.5;
            break;
        default:
            c.b = 1.0;
            break;
        case 3:
            float k = 0.25;
            c += k;
            switch (iFrame & 1) {
                case 0: c.r = 1.0; break;
                case 1: c.g = 1.0;
            }
            break;
        case 4: {
            for (int i = 0; i < 10; i++) {
                if (i == 3) break;
                c += 0.1;
            }
        }
    }
    switch (uint(mode)) {
        case 0u: c *= 0.5; break;
        default: c *= 0.9;
    }
    for (int i = 0; i < 4; i++) {
        switch (i) {
            case 1: continue;
            default: c += 0.01;
        }
    }
    switch (mode) { }
    fragColor = vec4(c, 1.0);
}
