// rule: 8.5 Geometric Functions: length takes a float vector
// error: 'length' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(length(ivec2(3, 4)));
}
