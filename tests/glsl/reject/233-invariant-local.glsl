// rule: 4.6 Variance and the Invariant Qualifier: invariant is used at global scope only
// error: 'invariant' : not allowed in nested scope
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    invariant float x = 1.0;
    fragColor = vec4(x);
}
