// exercises: 5.4.2 vector constructors: one scalar (replicated), from scalars, from mixed scalars and vectors, truncating a larger vector, from a matrix, converting between vector base types
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 p = fragCoord / iResolution.xy;
    vec4 a = vec4(0.5);
    vec4 b = vec4(p.x, p.y, 0.0, 1.0);
    vec4 c = vec4(p, p);
    vec4 d = vec4(p, 0.0, 1.0);
    vec4 e = vec4(0.0, p, 1.0);
    vec4 f = vec4(vec3(p, 0.5), 1.0);
    vec4 g = vec4(1.0, vec3(p, 0.5));
    vec3 h = vec3(b);
    vec2 i = vec2(vec3(1.0, 2.0, 3.0));
    vec3 j = vec3(vec2(1.0), vec2(2.0));
    vec4 k = vec4(mat2(p, p));
    vec3 l = vec3(mat3(1.0));
    vec2 m = vec2(mat4(2.0));
    vec4 n = vec4(ivec4(1, 2, 3, 4)) + vec4(uvec4(1u)) + vec4(bvec4(true, false, true, false));
    ivec3 o = ivec3(vec3(1.5, -2.5, 3.0)) + ivec3(uvec3(2u)) + ivec3(bvec3(true));
    uvec2 q = uvec2(vec2(3.5)) + uvec2(ivec2(4)) + uvec2(bvec2(false, true));
    bvec4 r = bvec4(vec4(0.0, 1.0, 0.0, 2.0));
    bvec2 s = bvec2(ivec2(0, 3)), t = bvec2(uvec2(1u, 0u));
    ivec4 u = ivec4(p, 1, true);
    uvec3 v = uvec3(1, 2.0, false);
    bvec3 w = bvec3(1, 0.0, true);
    vec4 x = vec4(ivec2(1), uvec2(2u));
    fragColor = (a + b + c + d + e + f + g + vec4(h, 1.0) + vec4(i, j.xy) + k + vec4(l, 1.0) + vec4(m, m) + n
                + vec4(o, 1.0) + vec4(q, q) + vec4(r) + vec4(s, t) + vec4(u) + vec4(v, 1.0) + vec4(w, false) + x) / 40.0;
}
