// exercises: bvec values: constructors, component access and swizzles, == and != on bvec, any/all/not, relational functions feeding mix and ?:
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 p = fragCoord / iResolution.xy;
    bvec2 a = greaterThan(p, vec2(0.5));
    bvec2 b = bvec2(p.x < 0.25, true);
    bvec4 c = bvec4(a, b.yx);
    bvec3 d = c.xyz;
    d.z = !d.x;
    bool same = a == b, diff = a != b.yx;
    vec2 chosen = mix(vec2(0.0), vec2(1.0), a);
    vec4 q = vec4(c);
    fragColor = vec4(chosen, any(not(d)) ? q.z : q.w, all(c) || same || diff ? 1.0 : 0.0);
}
