// rule: 4.6 Variance and the Invariant Qualifier: in a fragment shader, inputs cannot be declared invariant
// error: 'invariant' : can only apply to an output
invariant in vec2 uv;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(uv, 0.0, 1.0);
}
