// exercises: 3.3 directives inside function bodies: #define, #undef, #if, #pragma and the null directive between statements
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float a = 1.0;
#define LOCAL_SCALE 0.5
    a *= LOCAL_SCALE;
#undef LOCAL_SCALE
#pragma debug(on)
#
#if defined(LOCAL_SCALE)
    a = 0.0;
#else
    a += 0.25;
#endif
    fragColor = vec4(a);
}
