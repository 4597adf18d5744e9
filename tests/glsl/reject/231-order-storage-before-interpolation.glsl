// rule: 4.7 Order of Qualification: interpolation qualifiers come before the storage qualifier
// error: '' : interpolation qualifiers must appear before storage and precision qualifiers
in flat int id;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(float(id));
}
