// rule: 8.7 Vector Relational Functions: any takes a bvec
// error: 'any' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    bool b = any(fragCoord);
    fragColor = vec4(b ? 1.0 : 0.0);
}
