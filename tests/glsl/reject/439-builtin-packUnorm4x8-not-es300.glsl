// rule: 8 Built-in Functions: packUnorm4x8 is not an ES 3.00 built-in
// error: 'packUnorm4x8' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(float(packUnorm4x8(vec4(1.0))));
}
