// rule: 5.5 Vector Components: scalars cannot be swizzled in ES (no `f.xxx`)
// error: 'scalar swizzle' : not supported with this profile: es
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float f = 1.0;
    fragColor = vec4(f.xxx, 1.0);
}
