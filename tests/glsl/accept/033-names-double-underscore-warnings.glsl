// exercises: 3.3/3.7 names containing __ are reserved but using them is not an error (glslang warns only): variables, functions, macros (#define and #undef)
#define MY__MACRO 1.0
#define __LEADING 2.0
#undef MY__MACRO
#define MY__MACRO 3.0
float helper__fn(float x__y) { return x__y; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float a__b = helper__fn(MY__MACRO) + __LEADING;
    fragColor = vec4(a__b * 0.1);
}
