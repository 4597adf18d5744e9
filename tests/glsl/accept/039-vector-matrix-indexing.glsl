// exercises: 5.5/5.6 indexing vectors and matrices with constant and dynamic indices, column then row indexing, writes through indices, matrix columns as vectors
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec4 v = vec4(1.0, 2.0, 3.0, 4.0);
    mat3 m = mat3(1.0);
    int k = int(fragCoord.x) % 3;
    v[0] = v[3];
    v[k] += 1.0;
    m[1] = vec3(0.5);
    m[2][k] = 2.0;
    m[k][2] = v[k];
    vec3 col = m[k] + m[0].zyx;
    float last = v[v.x > 0.0 ? 3 : 0] + m[2][2];
    fragColor = vec4(col * 0.25, last * 0.1);
}
