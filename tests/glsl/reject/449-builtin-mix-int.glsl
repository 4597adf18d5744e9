// rule: 8.3 Common Functions: mix has no integer overloads in ES 3.00
// error: 'specific signature of builtin mix' : required extension not requested: GL_EXT_shader_integer_mix
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    int m = mix(1, 2, true);
    fragColor = vec4(float(m));
}
