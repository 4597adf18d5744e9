// rule: 3.4 Comments: comments do not nest; the first */ ends the comment
// error: '' : syntax error, unexpected IDENTIFIER
/* outer /* inner */ still outer */
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(1.0);
}
