// rule: 4.2 Scoping: a function must be declared before it is called
// error: 'later' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(later());
}
float later() { return 1.0; }
