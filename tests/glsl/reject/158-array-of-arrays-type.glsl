// rule: 4.1.9 Arrays: ES 3.00 has only one-dimensional arrays (array type as element)
// error: 'arrays of arrays' : not supported for this version or the enabled extensions
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float[2] a[3];
    fragColor = vec4(1.0);
}
