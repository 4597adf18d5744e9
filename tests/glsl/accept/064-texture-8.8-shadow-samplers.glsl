// exercises: 8.8 every texture lookup overload for sampler2DShadow, samplerCubeShadow, sampler2DArrayShadow
precision mediump sampler2DShadow;
precision mediump samplerCubeShadow;
precision mediump sampler2DArrayShadow;
uniform sampler2DShadow sh2;
uniform samplerCubeShadow shc;
uniform sampler2DArrayShadow sha;

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    vec3 dir = normalize(vec3(uv * 2.0 - 1.0, 1.0));
    vec2 dx = dFdx(uv), dy = dFdy(uv);
    float s = 0.0;
    { ivec2 r = textureSize(sh2, 0); s += dot(vec2(r), vec2(1.0)); }
    { ivec2 r = textureSize(shc, 0); s += dot(vec2(r), vec2(1.0)); }
    { ivec3 r = textureSize(sha, 0); s += dot(vec3(r), vec3(1.0)); }
    { float r = texture(sh2, vec3(uv, 0.5)); s += r; }
    { float r = texture(sh2, vec3(uv, 0.5), 0.5); s += r; }
    { float r = texture(shc, vec4(dir, 0.5)); s += r; }
    { float r = texture(shc, vec4(dir, 0.5), 0.5); s += r; }
    { float r = texture(sha, vec4(uv, 1.0, 0.5)); s += r; }
    { float r = textureProj(sh2, vec4(uv, 0.5, 2.0)); s += r; }
    { float r = textureProj(sh2, vec4(uv, 0.5, 2.0), 0.5); s += r; }
    { float r = textureLod(sh2, vec3(uv, 0.5), 0.0); s += r; }
    { float r = textureOffset(sh2, vec3(uv, 0.5), ivec2(1)); s += r; }
    { float r = textureOffset(sh2, vec3(uv, 0.5), ivec2(1), 0.5); s += r; }
    { float r = textureProjOffset(sh2, vec4(uv, 0.5, 2.0), ivec2(1)); s += r; }
    { float r = textureProjOffset(sh2, vec4(uv, 0.5, 2.0), ivec2(1), 0.5); s += r; }
    { float r = textureLodOffset(sh2, vec3(uv, 0.5), 0.0, ivec2(1)); s += r; }
    { float r = textureProjLod(sh2, vec4(uv, 0.5, 2.0), 0.0); s += r; }
    { float r = textureProjLodOffset(sh2, vec4(uv, 0.5, 2.0), 0.0, ivec2(1)); s += r; }
    { float r = textureGrad(sh2, vec3(uv, 0.5), dx, dy); s += r; }
    { float r = textureGrad(shc, vec4(dir, 0.5), vec3(dx, 0.0), vec3(dy, 0.0)); s += r; }
    { float r = textureGrad(sha, vec4(uv, 1.0, 0.5), dx, dy); s += r; }
    { float r = textureGradOffset(sh2, vec3(uv, 0.5), dx, dy, ivec2(1)); s += r; }
    { float r = textureGradOffset(sha, vec4(uv, 1.0, 0.5), dx, dy, ivec2(1)); s += r; }
    { float r = textureProjGrad(sh2, vec4(uv, 0.5, 2.0), dx, dy); s += r; }
    { float r = textureProjGradOffset(sh2, vec4(uv, 0.5, 2.0), dx, dy, ivec2(1)); s += r; }
    fragColor = vec4(vec3(fract(s)), 1.0);
}
