// rule: 4.2 Scoping: the prelude declares iTime; the program cannot declare it again
// error: 'iTime' : redefinition
uniform float iTime;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
