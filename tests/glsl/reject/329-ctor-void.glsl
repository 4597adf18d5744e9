// rule: 5.4 Constructors: there is no void constructor
// error: 'void' : cannot construct this type
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    void(1.0);
    fragColor = vec4(1.0);
}
