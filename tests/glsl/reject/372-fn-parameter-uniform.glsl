// rule: 4.4 Parameter Qualifiers: parameters take in, out, inout and const only
// error: 'uniform' : storage qualifier not allowed on function parameter
float f(uniform float x) { return x; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(f(1.0));
}
