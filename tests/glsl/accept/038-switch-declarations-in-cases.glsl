// exercises: 6.2 declarations as statements directly under a case label (no braces) and visible in later cases of the same switch body
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(0.0);
    switch (int(fragCoord.x) % 3) {
        case 0:
            float shade = 0.25;
            fragColor = vec4(shade);
            break;
        case 1:
            shade = 0.5;
            fragColor = vec4(shade);
            break;
        default:
            fragColor = vec4(1.0);
    }
}
