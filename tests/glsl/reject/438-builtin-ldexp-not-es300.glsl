// rule: 8 Built-in Functions: ldexp is not an ES 3.00 built-in
// error: 'ldexp' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(ldexp(1.0, 3));
}
