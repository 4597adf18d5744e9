// exercises: 5.5 swizzle reads with xyzw, rgba and stpq (repeats allowed when reading), writes to distinct-component swizzles in any order, compound assignment and ++ on swizzles, swizzles of expressions, array elements and struct members
struct Light { vec3 colour; };
vec3 tint() { return vec3(0.1, 0.2, 0.3); }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec4 v = vec4(fragCoord, 0.5, 1.0);
    vec2 a = v.xy + v.rg + v.st + v.yx + v.ba + v.qp;
    vec3 b = v.xxx + v.rgb + v.stp + v.zyx + v.bgr;
    vec4 c = v.xyzw + v.wzyx + v.rrgg + v.stpq + v.qqqq;
    float d = v.x + v.g + v.p + v.a + v[2];
    vec4 w = vec4(0.0);
    w.x = 1.0;
    w.yz = vec2(2.0, 3.0);
    w.wx = vec2(4.0, 5.0);
    w.bgr = vec3(1.0);
    w.stpq = v;
    w.zywx = v.xyzw;
    w.xy += a;
    w.zw *= 2.0;
    w.r++;
    --w.q;
    w.yx.x = 0.5;
    vec3 t = tint().zyx + tint().bgr;
    vec4 arr[2];
    arr[0] = v;
    arr[1].xz = arr[0].zx;
    Light l = Light(vec3(1.0));
    l.colour.gb = vec2(0.5);
    float e = vec4(1.0, 2.0, 3.0, 4.0).w + (v + w).x + vec2(d).y;
    fragColor = vec4(a, b.x + c.y, e) * 0.001 + vec4(t, 0.0) + arr[1] * 0.0 + vec4(l.colour, w.x) * 0.1;
}
