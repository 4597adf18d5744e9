// exercises: 3.4 comments in odd places (inside expressions, between a function name and its parenthesis, across lines, containing // and /* and non-ASCII: éè — π ≈ 3.14), 3.2 line continuation in code, in an identifier, in a number and in a macro; a // comment continued by a backslash (glslang warns)
/* a block comment
   spanning lines // with a line comment inside
   and a second /* opener */
#define LONG_MACRO(a, b) \
    ((a) + \
     (b))
// this line comment is continued \
   onto this line, which is still a comment
float tw/* a comment separates tokens like a space */;
float hel\
per(float x) { return x * 2.0; }
void mainImage(out vec4 fragColor, /* here */ in vec2 fragCoord) {
    float a = 1.0 /* inside */ + /* an */ 2.0; // end
    float b = helper /* between */ (a);
    float c = 12\
34.5;
    float d = LONG_MACRO(a, b);
    tw = 0.5;
    fragColor = vec4(a, b, c * 0.0001, d + tw) /*
    */ * 0.1;
}
