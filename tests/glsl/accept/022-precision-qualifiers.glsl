// exercises: 4.5 precision qualifiers on locals, globals, parameters, return types and struct members; precision statements at global and local scope (float, int, sampler types); lowp and mediump values mixed with highp in expressions
precision mediump float;
precision lowp int;
precision lowp samplerCube;
struct Sample { lowp vec4 colour; highp float depth; mediump int id; };
highp float g = 1.0;
mediump vec3 tone(lowp vec3 c, highp float exposure) {
    return c * exposure;
}
lowp float quant(mediump float x) { return floor(x * 4.0) / 4.0; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    precision highp float;
    highp vec2 p = fragCoord / iResolution.xy;
    mediump float m = p.x;
    lowp float l = p.y;
    lowp int li = 3;
    mediump ivec2 mi = ivec2(1);
    highp uint hu = 7u;
    Sample s = Sample(vec4(m, l, 0.0, 1.0), 1.0, li);
    float mixed = m * l + g;
    fragColor = vec4(tone(s.colour.rgb, mixed) * quant(m), float(mi.x + s.id) + float(hu) * 0.0);
}
