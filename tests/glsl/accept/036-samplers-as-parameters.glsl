// exercises: 4.1.7 samplers passed to functions (in and const in), arrays of sampler uniforms indexed by constant expressions, a uniform struct holding a sampler, samplerCube with its default precision
uniform sampler2D layers[3];
struct TexParams { sampler2D tex; vec2 scale; };
uniform TexParams params;
uniform samplerCube env;
vec4 tap(sampler2D s, vec2 uv) { return texture(s, uv); }
vec4 tap2(const in sampler2D s, vec2 uv) { return tap(s, uv * 2.0); }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    const int LAST = 2;
    vec4 c = tap(iChannel0, uv) + tap2(iChannel1, uv) + texture(layers[0], uv) + texture(layers[LAST], uv);
    c += texture(params.tex, uv * params.scale);
    c += texture(env, vec3(uv, 1.0));
    for (int i = 0; i < 3; i++) c += texture(layers[1], uv) * 0.0;
    fragColor = c / 6.0;
}
