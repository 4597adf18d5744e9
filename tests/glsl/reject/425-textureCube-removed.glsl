// rule: 8.8 Texture Lookup Functions: textureCube does not exist in ES 3.00
// error: 'textureCube' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = textureCube(iChannel0, vec3(0.5));
}
