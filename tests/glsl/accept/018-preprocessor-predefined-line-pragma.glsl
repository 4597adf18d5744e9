// exercises: 3.3 __LINE__, __FILE__, __VERSION__ and GL_ES, #line with one and two numbers and with an expression, #pragma (standard and unknown), the null directive, spaces and comments around # and in directives
#if __VERSION__ != 300 || GL_ES != 1
#error expected ES 3.00
#endif
const int L0 = __LINE__;
#line 100
const int L1 = __LINE__;
#line 200 1
const int L2 = __LINE__ + __FILE__;
#line 10 * 30
#pragma optimize(on)
#pragma debug(off)
#pragma rasterd_unknown_pragma with (any) tokens
#
  #  define SPACED 1
/* comment */ # /* comment */ define COMMENTED 2 // trailing
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(float(L0 + L1 + L2 + __LINE__), float(SPACED + COMMENTED), 0.0, 1.0) * 0.001;
}
