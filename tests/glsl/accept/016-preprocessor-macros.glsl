// exercises: 3.3 object-like and function-like macros, nested expansion, macros calling macros, arguments containing parentheses and commas, multi-line calls, identical redefinition (whitespace amount may differ), #undef then a new definition, a macro named like a keyword, a function-like macro name used without arguments
#define PI 3.14159265
#define TAU (2.0 * PI)
#define SQ(x) ((x) * (x))
#define MAX3(a, b, c) max(a, max(b, c))
#define ROT(a) mat2(cos(a), sin(a), -sin(a), cos(a))
#define APPLY(f, v) f(v)
#define NOARGS() 1.0
#define EMPTY
#define SCALE 2.0
#define SCALE    2.0
#define STEP 1.0
#undef STEP
#define STEP 0.5
#define saturate(x) clamp(x, 0.0, 1.0)
#define mediumP mediump
#define LINE_COUNT __LINE__
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 p = fragCoord / iResolution.xy EMPTY;
    float saturate = 0.25;
    mediumP float a = SQ(TAU) * 0.01 + MAX3(p.x, p.y, STEP) + NOARGS();
    vec2 q = ROT(iTime) * p;
    float b = APPLY(sin, a) + APPLY(length, vec2(p.x, p.y));
    float c = MAX3(
        SQ(p.x),
        SQ(p.y),
        0.1
    );
    fragColor = vec4(saturate(a + b + c) * SCALE + saturate, q, float(LINE_COUNT) * 0.0);
}
