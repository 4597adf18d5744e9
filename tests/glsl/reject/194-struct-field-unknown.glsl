// rule: 5.7 Structure and Array Operations: a field selection must name a member
// error: 'dir' : no such field in structure 'r'
struct Ray { vec3 o; vec3 d; };
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    Ray r = Ray(vec3(0.0), vec3(1.0));
    fragColor = vec4(r.dir, 1.0);
}
