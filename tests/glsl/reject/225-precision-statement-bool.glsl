// rule: 4.5 Precision and Precision Qualifiers: a precision statement applies to float, int and sampler types only
// error: 'bool' : cannot apply precision statement to this type; use 'float', 'int' or a sampler type
precision highp bool;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
