// exercises: 5.4.3 struct constructors (nested, with array and matrix members), 5.4.4 array constructors sized and unsized, arrays of structs and of vectors, constructors as arguments
struct Material { vec3 albedo; float roughness; };
struct Sphere { vec3 centre; float radius; Material material; float weights[3]; mat2 rot; };
float total(float w[3]) { return w[0] + w[1] + w[2]; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 p = fragCoord / iResolution.xy;
    Material m = Material(vec3(p, 0.5), 0.25);
    Sphere s = Sphere(vec3(0.0), 1.0, m, float[3](0.2, 0.3, 0.5), mat2(1.0));
    Sphere t = Sphere(vec3(1.0), 0.5, Material(vec3(1.0), 0.9), float[](1.0, 2.0, 3.0), mat2(p, p));
    Sphere list[2] = Sphere[2](s, t);
    Material mats[] = Material[](m, Material(vec3(0.0), 1.0), s.material);
    vec2 pts[4] = vec2[4](vec2(0.0), vec2(1.0, 0.0), p, vec2(p.y, p.x));
    vec3 cols[] = vec3[](vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0));
    int ids[3] = int[3](1, 2, iFrame);
    bool flags[2] = bool[](true, p.x > 0.5);
    float w = total(float[3](p.x, p.y, 1.0)) + total(s.weights) + total(list[1].weights);
    fragColor = vec4(list[0].material.albedo * mats[2].roughness + cols[1] * float(ids[2] % 2), w * 0.1 + pts[2].x + (flags[1] ? 0.5 : 0.0) + float(mats.length()));
}
