// rule: 4.3 Storage Qualifiers: a global initialiser must be a constant expression in ES 3.00
// error: 'non-constant global initializer (needs GL_EXT_shader_non_constant_global_initializers)' : not supported fo...
float start = iTime;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(start);
}
