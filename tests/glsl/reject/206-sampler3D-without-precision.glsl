// rule: 4.5 Precision and Precision Qualifiers: sampler3D has no default precision; it must be given one
// error: 'sampler/image' : type requires declaration of default precision qualifier
uniform sampler3D volume;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = texture(volume, vec3(0.5));
}
