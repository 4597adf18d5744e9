// rule: 5.7 Structure and Array Operations: only arrays, vectors and matrices can be indexed
// error: 'f' : left of '[' is not of type array, matrix, or vector
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float f = 1.0;
    fragColor = vec4(f[0]);
}
