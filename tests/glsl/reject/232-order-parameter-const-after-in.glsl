// rule: 4.7 Order of Qualification: a parameter's const comes before in
// error: '' : in/out must appear before const
float f(in const float x) { return x; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(f(1.0));
}
