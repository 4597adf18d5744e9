// exercises: 4.1.8 structs: several declarators in one definition, an anonymous struct variable, a struct used as member of another, a struct defined inside a function, structs as parameters, return values and out parameters, assignment and equality
struct Ray { vec3 origin; vec3 dir; } primary, secondary;
struct Hit { float t; Ray ray; };
struct { float near; float far; } range;
Hit trace(Ray r, float t) {
    return Hit(t, r);
}
void reflectRay(inout Ray r, vec3 n) {
    r.dir = reflect(r.dir, n);
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 p = fragCoord / iResolution.xy;
    range.near = 0.0;
    range.far = 100.0;
    primary = Ray(vec3(0.0), normalize(vec3(p - 0.5, 1.0)));
    secondary = primary;
    reflectRay(secondary, vec3(0.0, 0.0, -1.0));
    Hit h = trace(primary, 2.0);
    struct Local { int id; float w; };
    Local loc = Local(1, 0.5);
    bool same = h.ray == primary && !(primary == secondary);
    fragColor = vec4(h.ray.dir * loc.w + secondary.dir * 0.25, same ? range.far * 0.01 : range.near);
}
