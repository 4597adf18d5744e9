// exercises: 4.1.9 global arrays with sizes taken from their initialiser (plain and const), arrays of vectors and structs at global scope, const arrays indexed in loops
const vec3 PALETTE[] = vec3[](vec3(0.1, 0.2, 0.3), vec3(0.4, 0.5, 0.6), vec3(0.7, 0.8, 0.9));
struct Stop { float at; vec3 colour; };
const Stop STOPS[2] = Stop[2](Stop(0.0, vec3(0.0)), Stop(1.0, vec3(1.0)));
const float KERNEL[] = float[](1.0, 4.0, 6.0, 4.0, 1.0);
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    vec3 c = vec3(0.0);
    float wsum = 0.0;
    for (int i = 0; i < KERNEL.length(); i++) {
        float w = KERNEL[i];
        c += w * texture(iChannel0, uv + vec2(float(i - 2), 0.0) / iResolution.xy).rgb;
        wsum += w;
    }
    c /= wsum;
    c = mix(c, PALETTE[int(uv.x * 2.99)], 0.5);
    c = mix(c, mix(STOPS[0].colour, STOPS[1].colour, uv.y), 0.1);
    fragColor = vec4(c, 1.0);
}
