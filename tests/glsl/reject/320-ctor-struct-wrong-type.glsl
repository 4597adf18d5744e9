// rule: 5.4.3 Structure Constructors: arguments must have the member types in order
// error: 'constructor' : cannot convert parameter 2 from ' const float' to ' global highp int'
struct Hit { float t; int id; };
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    Hit h = Hit(1.0, 2.0);
    fragColor = vec4(h.t);
}
