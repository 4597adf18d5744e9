// rule: 6.1 Function Definitions: the epilogue calls mainImage(vec4, vec2); a mainImage taking a vec3 does not match
// error: 'mainImage' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec3 fragCoord) {
    fragColor = vec4(1.0);
}
