// rule: 4.1.8 Structures: member names of a struct must be distinct
// error: '' : duplicate member name: o
struct Ray { vec3 o; vec3 o; };
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
