// rule: 8 Built-in Functions: noise1 is not an ES 3.00 built-in
// error: 'noise1' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(noise1(1.0));
}
