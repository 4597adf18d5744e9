// rule: 4.1.1 Void: void is only a function return type
// error: 'nothing' : illegal use of type 'void'
void nothing;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
