// exercises: mainImage declared with a different but matching signature: no `in` keyword, other parameter names, precision qualifiers, a prototype first; the epilogue's call mainImage(vec4, vec2) still resolves
void mainImage(out highp vec4 colour, highp vec2 pixel);
void mainImage(out highp vec4 colour, highp vec2 pixel) {
    colour = vec4(pixel / iResolution.xy, 0.0, 1.0);
}
