// rule: 4.1.10 Implicit Conversions: there are no implicit conversions; a struct constructor's arguments must have the field types
// error: 'constructor' : cannot convert parameter 2 from ' const int' to ' global highp float'
struct Light { vec3 colour; float power; };
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    Light l = Light(vec3(1.0), 2);
    fragColor = vec4(l.colour * l.power, 1.0);
}
