// exercises: 4.3 global declarations a program may add to the prelude's: in variables with smooth/flat/centroid (integer inputs flat), uniforms of scalar, bool, struct and array type, uniform blocks (std140, with and without instance name). (No extra out: see glslang-differs/extra-fragment-output-without-location.)
smooth in vec2 vUv;
centroid in vec3 vNormal;
smooth centroid in float vFog;
flat in int vId;
flat in uvec2 vMask;
in vec4 vColour;
uniform float uGain;
uniform bool uEnabled;
uniform vec3 uPalette[4];
struct Params { vec2 offset; float scale; };
uniform Params uParams;
layout(std140) uniform Globals { mat4 view; vec4 tint; } globals;
uniform Extra { float extraScale; };
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec3 c = uEnabled ? uPalette[vId & 3] * uGain : vNormal * vFog;
    vec2 q = vUv * uParams.scale + uParams.offset + vec2(vMask);
    fragColor = vec4(c, q.x) + globals.view[0] + vColour + globals.tint * extraScale;
}
