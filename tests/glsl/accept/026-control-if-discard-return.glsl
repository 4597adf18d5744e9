// exercises: 6.2 if/else chains and dangling else, 6.4 discard (also in a helper), return in mainImage and in a void helper, unreachable code after return, nested blocks and empty statements
void killIfNegative(float x) {
    if (x < 0.0) discard;
}
float classify(float x) {
    if (x < 0.25) return 0.0;
    else if (x < 0.5) return 1.0;
    else if (x < 0.75) return 2.0;
    else return 3.0;
    float unreachable = 1.0;
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 p = fragCoord / iResolution.xy;
    killIfNegative(p.x - 0.001);
    if (p.y > 0.99) discard;
    ;;
    { { } }
    fragColor = vec4(0.0);
    if (p.x > 0.5)
        if (p.y > 0.5) fragColor.r = 1.0;
        else fragColor.g = 1.0;
    if (iTime < 0.0) {
        fragColor = vec4(1.0);
        return;
    }
    fragColor.b = classify(p.x) / 3.0;
    return;
}
