// rule: 4.1.8 Structures: a member array must have a size
// error: '' : array size required
struct Path { vec2 points[]; };
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
