// rule: 5.1 Operators: a float has no fields
// error: 'scalar swizzle' : not supported with this profile: es
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float f = 1.0;
    fragColor = vec4(f.value);
}
