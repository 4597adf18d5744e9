// exercises: 3.3 #if/#ifdef/#ifndef/#elif/#else/#endif, nesting, defined with and without parentheses, integer arithmetic, logical, bitwise, shift and relational operators, octal and hex numbers, short-circuit over undefined names, skipped groups holding anything but directives, #error in a skipped group
#define QUALITY 2
#if defined(GL_ES) && defined GL_ES && !defined(NOT_DEFINED)
#define ES 1
#else
#error not es
#endif
#if (QUALITY << 2) == 8 && (7 & 3) == 3 && (1 | 2) == 3 && (5 ^ 1) == 4 && ~0 == -1 && !0 && 7 / 2 == 3 && 7 % 4 == 3
#define OPS_OK 1
#endif
#if -3 < 0 && 2 >= 2 && 3 > 2 && 2 <= 2 && 1 != 2 && 0x10 == 16 && 010 == 8 && (1 + 2) * 3 - 4 == 5 && +1 == 1
#define MORE_OK 1
#endif
#if 1 || UNDEFINED_NAME
#define SHORT_OR 1
#endif
#if 0 && UNDEFINED_NAME
#else
#define SHORT_AND 1
#endif
#ifdef QUALITY
#  if QUALITY > 2
#    define STEPS 128
#  elif QUALITY > 1
#    define STEPS 64
#  else
#    define STEPS 32
#  endif
#endif
#ifndef STEPS
#error no steps
#endif
#if 0
this is skipped: $ @ ` \ 1f 0.5u #notadirective not even ( balanced
#error skipped
#if 1/0
#endif
#else
#define SKIPPED_OK 1
#endif
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(float(ES + OPS_OK + MORE_OK + SHORT_OR + SHORT_AND + SKIPPED_OK), float(STEPS) / 64.0, 0.0, 1.0);
}
