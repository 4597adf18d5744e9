// exercises: a typical ShaderToy buffer pass: texelFetch of the previous frame in iChannel0 with integer coordinates, a neighbourhood loop with continue, integer rules, iFrame initialisation, iMouse painting
int cell(ivec2 p) {
    ivec2 size = ivec2(iResolution.xy);
    return texelFetch(iChannel0, (p + size) % size, 0).r > 0.5 ? 1 : 0;
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    ivec2 p = ivec2(fragCoord);
    int n = 0;
    for (int y = -1; y <= 1; y++)
        for (int x = -1; x <= 1; x++) {
            if (x == 0 && y == 0) continue;
            n += cell(p + ivec2(x, y));
        }
    int alive = cell(p);
    int next = (n == 3 || (alive == 1 && n == 2)) ? 1 : 0;
    if (iFrame == 0) next = int(fract(sin(dot(fragCoord, vec2(12.9898, 78.233))) * 43758.5453) > 0.6);
    if (iMouse.z > 0.0 && distance(fragCoord, iMouse.xy) < 5.0) next = 1;
    fragColor = vec4(vec3(float(next)), 1.0);
}
