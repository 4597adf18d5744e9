// rule: 4.1.8 Structures: a struct name can be defined only once in a scope
// error: 'Ray' : redefinition struct
struct Ray { vec3 o; vec3 d; };
struct Ray { vec3 origin; };
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    Ray r = Ray(vec3(0.0), vec3(1.0));
    fragColor = vec4(r.d, 1.0);
}
