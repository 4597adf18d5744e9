// rule: 4.1.7 Sampler Types: a struct containing a sampler can only be a uniform (or a parameter)
// error: 'structure' : non-uniform struct contains a sampler or image: t
struct Tex { sampler2D s; float scale; };
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    Tex t;
    fragColor = vec4(1.0);
}
