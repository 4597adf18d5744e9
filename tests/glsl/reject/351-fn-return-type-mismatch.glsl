// rule: 6.4 Jumps: the returned value must have the function's return type
// error: 'return' : cannot convert return value to function return type
vec2 f() { return vec3(1.0); }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(f(), 0.0, 1.0);
}
