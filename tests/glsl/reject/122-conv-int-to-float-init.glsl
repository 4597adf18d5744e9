// rule: 4.1.10 Implicit Conversions: there are no implicit conversions; an int cannot initialise a float
// error: '=' : cannot convert from ' const int' to ' temp highp float'
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float x = 1;
    fragColor = vec4(x);
}
