// rule: 6.1.1 Function Calling Conventions: an out argument must be an l-value (a repeated swizzle is not)
// error: 'assign' : l-value of swizzle cannot have duplicate components
void set(out vec2 x) { x = vec2(1.0); }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec4 a = vec4(0.0);
    set(a.xx);
    fragColor = a;
}
