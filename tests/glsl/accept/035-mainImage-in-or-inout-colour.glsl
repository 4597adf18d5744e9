// exercises: mainImage whose colour parameter is inout: the epilogue passes an l-value, so in, out and inout all match
void mainImage(inout vec4 fragColor, in vec2 fragCoord) {
    fragColor += vec4(fragCoord / iResolution.xy, 0.0, 1.0);
}
