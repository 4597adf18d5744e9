// rule: 4.2 Scoping: a variable's scope starts after its initialiser; a new local named like nothing before it is undeclared there
// error: 'total' : undeclared identifier
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float total = total + 1.0;
    fragColor = vec4(total);
}
