// rule: 8.7 Vector Relational Functions: lessThan takes vectors, not scalars
// error: 'lessThan' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    bool b = lessThan(iTime, 1.0);
    fragColor = vec4(b ? 1.0 : 0.0);
}
