// exercises: 5.4.1 scalar constructors converting between float, int, uint and bool, and taking the first component of a vector or matrix
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float f = fragCoord.x * 0.01;
    int i = int(fragCoord.y);
    uint u = uint(iFrame);
    bool b = f > 1.0;
    float f1 = float(i) + float(u) + float(b) + float(f);
    int i1 = int(f) + int(u) + int(b) + int(i) + int(-2.7);
    uint u1 = uint(f) + uint(i) + uint(b) + uint(u) + uint(-1);
    bool b1 = bool(f) || bool(i) || bool(u) || bool(b);
    float f2 = float(vec3(f, 2.0, 3.0)) + float(ivec2(i)) + float(bvec4(b)) + float(mat2(f)) + float(uvec3(u));
    int i2 = int(vec2(1.5)) + int(uvec2(3u)) + int(bvec3(true));
    uint u2 = uint(ivec4(5)) + uint(vec2(2.5));
    bool b2 = bool(vec2(0.0)) || bool(ivec3(0)) || bool(uvec2(1u));
    fragColor = vec4(f1 + f2, float(i1 + i2), float(u1 + u2), b1 || b2 ? 1.0 : 0.0);
}
