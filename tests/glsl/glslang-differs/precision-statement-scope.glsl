// rule: 4.5.4 Default Precision Qualifiers: a precision statement has the scope of a variable declared where it stands; sampler3D has no default precision outside the function that gave it one
// glslang: accepts: glslang keeps a sampler type's default precision from a function's body for the rest of the shader. rasterd rejects
void declareDefaults() {
    precision lowp sampler3D;
}
uniform sampler3D volume;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = texture(volume, vec3(0.5));
}
