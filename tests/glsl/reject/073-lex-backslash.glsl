// rule: 3.1 Character Set: a backslash is only allowed as line continuation
// error: '\' : illegal use of escape character
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float x = 1.0 \ 2.0;
    fragColor = vec4(x);
}
