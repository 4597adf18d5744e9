// rule: 4.7 Order of Qualification: the precision qualifier comes last (`const highp`, not `highp const`)
// error: '' : precision qualifier must appear as last qualifier
highp const float PI = 3.14159265;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(PI);
}
