// rule: 3.6 Keywords: `hvec3` is reserved for future use; using it is an error
// error: 'hvec3' : Reserved word.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float hvec3 = 1.0;
    fragColor = vec4(hvec3);
}
