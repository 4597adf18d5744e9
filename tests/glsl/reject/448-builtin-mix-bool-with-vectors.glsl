// rule: 8.3 Common Functions: mix with a bool selector needs a bvec of the vector's size
// error: 'mix' : no matching overloaded function found
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec3 c = mix(vec3(0.0), vec3(1.0), true);
    fragColor = vec4(c, 1.0);
}
