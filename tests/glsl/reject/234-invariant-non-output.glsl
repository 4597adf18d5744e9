// rule: 4.6 Variance and the Invariant Qualifier: only outputs can be declared invariant
// error: 'invariant' : can only apply to an output
invariant uniform float level;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(level);
}
