// exercises: 8.8 every texture lookup overload for usampler2D, usampler3D, usamplerCube, usampler2DArray (uint results)
precision highp usampler2D;
precision highp usampler3D;
precision highp usamplerCube;
precision highp usampler2DArray;
uniform usampler2D us2;
uniform usampler3D us3;
uniform usamplerCube usc;
uniform usampler2DArray usa;

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    vec3 dir = normalize(vec3(uv * 2.0 - 1.0, 1.0));
    vec2 dx = dFdx(uv), dy = dFdy(uv);
    float s = 0.0;
    { ivec2 r = textureSize(us2, 0); s += dot(vec2(r), vec2(1.0)); }
    { ivec3 r = textureSize(us3, 1); s += dot(vec3(r), vec3(1.0)); }
    { ivec2 r = textureSize(usc, 0); s += dot(vec2(r), vec2(1.0)); }
    { ivec3 r = textureSize(usa, 0); s += dot(vec3(r), vec3(1.0)); }
    { uvec4 r = texture(us2, uv); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = texture(us3, vec3(uv, 0.5)); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = texture(usc, dir); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = texture(usa, vec3(uv, 1.0)); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureProj(us2, vec3(uv, 2.0)); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureProj(us2, vec4(uv, 0.0, 2.0)); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureProj(us3, vec4(uv, 0.5, 2.0)); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureOffset(us2, uv, ivec2(1, -1)); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureOffset(us3, vec3(uv, 0.5), ivec3(1, 0, -1)); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureOffset(usa, vec3(uv, 1.0), ivec2(-8, 7)); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureProjOffset(us2, vec3(uv, 2.0), ivec2(2)); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureProjOffset(us2, vec4(uv, 0.0, 2.0), ivec2(2)); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureProjOffset(us3, vec4(uv, 0.5, 2.0), ivec3(2)); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = texture(us2, uv, 0.5); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = texture(us3, vec3(uv, 0.5), 0.5); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = texture(usc, dir, 0.5); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = texture(usa, vec3(uv, 1.0), 0.5); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureProj(us2, vec3(uv, 2.0), 0.5); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureProj(us2, vec4(uv, 0.0, 2.0), 0.5); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureProj(us3, vec4(uv, 0.5, 2.0), 0.5); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureOffset(us2, uv, ivec2(1, -1), 0.5); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureOffset(us3, vec3(uv, 0.5), ivec3(1, 0, -1), 0.5); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureOffset(usa, vec3(uv, 1.0), ivec2(-8, 7), 0.5); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureProjOffset(us2, vec3(uv, 2.0), ivec2(2), 0.5); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureProjOffset(us2, vec4(uv, 0.0, 2.0), ivec2(2), 0.5); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureProjOffset(us3, vec4(uv, 0.5, 2.0), ivec3(2), 0.5); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureLod(us2, uv, 1.0); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureLod(us3, vec3(uv, 0.5), 1.0); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureLod(usc, dir, 1.0); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureLod(usa, vec3(uv, 1.0), 1.0); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = texelFetch(us2, ivec2(fragCoord), 0); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = texelFetch(us3, ivec3(fragCoord, 0), 0); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = texelFetch(usa, ivec3(fragCoord, 1), 0); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = texelFetchOffset(us2, ivec2(fragCoord), 0, ivec2(1)); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = texelFetchOffset(us3, ivec3(fragCoord, 0), 0, ivec3(1)); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = texelFetchOffset(usa, ivec3(fragCoord, 1), 0, ivec2(1)); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureLodOffset(us2, uv, 1.0, ivec2(1)); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureLodOffset(us3, vec3(uv, 0.5), 1.0, ivec3(1)); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureLodOffset(usa, vec3(uv, 1.0), 1.0, ivec2(1)); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureProjLod(us2, vec3(uv, 2.0), 1.0); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureProjLod(us2, vec4(uv, 0.0, 2.0), 1.0); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureProjLod(us3, vec4(uv, 0.5, 2.0), 1.0); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureProjLodOffset(us2, vec3(uv, 2.0), 1.0, ivec2(1)); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureProjLodOffset(us2, vec4(uv, 0.0, 2.0), 1.0, ivec2(1)); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureProjLodOffset(us3, vec4(uv, 0.5, 2.0), 1.0, ivec3(1)); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureGrad(us2, uv, dx, dy); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureGrad(us3, vec3(uv, 0.5), vec3(dx, 0.0), vec3(dy, 0.0)); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureGrad(usc, dir, vec3(dx, 0.0), vec3(dy, 0.0)); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureGrad(usa, vec3(uv, 1.0), dx, dy); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureGradOffset(us2, uv, dx, dy, ivec2(1)); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureGradOffset(us3, vec3(uv, 0.5), vec3(dx, 0.0), vec3(dy, 0.0), ivec3(1)); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureGradOffset(usa, vec3(uv, 1.0), dx, dy, ivec2(1)); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureProjGrad(us2, vec3(uv, 2.0), dx, dy); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureProjGrad(us2, vec4(uv, 0.0, 2.0), dx, dy); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureProjGrad(us3, vec4(uv, 0.5, 2.0), vec3(dx, 0.0), vec3(dy, 0.0)); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureProjGradOffset(us2, vec3(uv, 2.0), dx, dy, ivec2(1)); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureProjGradOffset(us2, vec4(uv, 0.0, 2.0), dx, dy, ivec2(1)); s += dot(vec4(r), vec4(1.0)); }
    { uvec4 r = textureProjGradOffset(us3, vec4(uv, 0.5, 2.0), vec3(dx, 0.0), vec3(dy, 0.0), ivec3(1)); s += dot(vec4(r), vec4(1.0)); }
    fragColor = vec4(vec3(fract(s)), 1.0);
}
