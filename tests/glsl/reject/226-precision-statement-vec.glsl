// rule: 4.5 Precision and Precision Qualifiers: a precision statement names a scalar type, not a vector
// error: 'float' : cannot apply precision statement to this type; use 'float', 'int' or a sampler type
precision mediump vec3;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
