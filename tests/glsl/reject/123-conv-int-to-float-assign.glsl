// rule: 4.1.10 Implicit Conversions: there are no implicit conversions; an int cannot be assigned to a float
// error: 'assign' : cannot convert from ' uniform highp int' to ' temp highp float'
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float x;
    x = iFrame;
    fragColor = vec4(x);
}
