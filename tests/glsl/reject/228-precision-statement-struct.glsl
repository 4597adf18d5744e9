// rule: 4.5 Precision and Precision Qualifiers: a precision statement cannot apply to a struct
// error: 'structure' : cannot apply precision statement to this type; use 'float', 'int' or a sampler type
struct S { float a; };
precision highp S;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
