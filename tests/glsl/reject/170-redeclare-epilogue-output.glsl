// rule: 4.2 Scoping: the epilogue declares rasterd_FragColor at global scope; a program global of that name clashes
// error: 'rasterd_FragColor' : redefinition
vec4 rasterd_FragColor;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
