// exercises: 4.1.9/5.7 arrays: sized and unsized-with-initialiser declarations (both syntaxes), .length(), constant and dynamic indexing, assignment and comparison of whole arrays, arrays as parameters, return values and out parameters, uint indices, uniform arrays indexed dynamically
const int N = 4;
float[N] ramp() {
    float r[N];
    for (int i = 0; i < N; i++) r[i] = float(i) / float(N - 1);
    return r;
}
void scale(inout float a[N], float k) {
    for (int i = 0; i < a.length(); ++i) a[i] *= k;
}
void fill(out vec2 pts[2]) {
    pts[0] = vec2(0.0);
    pts[1] = vec2(1.0);
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float a[N] = ramp();
    float b[N];
    b = a;
    scale(b, 0.5);
    float[3] c = float[3](1.0, 2.0, 3.0);
    float[] d = float[](4.0, 5.0);
    vec2 pts[2];
    fill(pts);
    int k = int(fragCoord.x) % N;
    uint uk = uint(k);
    float s = a[k] + b[uk] + c[2] + d[d.length() - 1] + pts[1].y;
    for (int i = 0; i < 4; i++) s += iChannelTime[i] + iChannelResolution[i].x * 0.0;
    s += iChannelTime[iFrame % 4];
    const int len = c.length();
    float e[len];
    e[len - 1] = float(len);
    bool same = a == b, differ = c != float[3](1.0, 2.0, 4.0);
    fragColor = vec4(fract(s), e[2] * 0.1, same ? 1.0 : 0.0, differ ? 1.0 : 0.0);
}
