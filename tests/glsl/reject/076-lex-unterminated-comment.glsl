// rule: 3.4 Comments: a /* comment must be closed
// error: 'comment' : End of input in comment
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
/* notes
