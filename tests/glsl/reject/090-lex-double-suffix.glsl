// rule: 4.1.4 Floats: there are no double literals (lf suffix) in ES
// error: 'double literal' : not supported with this profile: es
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float f = 1.0lf;
    fragColor = vec4(f);
}
