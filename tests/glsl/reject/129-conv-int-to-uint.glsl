// rule: 4.1.10 Implicit Conversions: there are no implicit conversions; an int literal cannot initialise a uint
// error: '=' : cannot convert from ' const int' to ' temp highp uint'
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    uint u = 1;
    fragColor = vec4(float(u));
}
