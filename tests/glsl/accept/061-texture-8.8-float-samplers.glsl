// exercises: 8.8 every texture lookup overload for sampler2D (the iChannels), sampler3D, samplerCube, sampler2DArray
precision highp sampler3D;
precision highp samplerCube;
precision highp sampler2DArray;
uniform sampler3D s3;
uniform samplerCube sc;
uniform sampler2DArray sa;

#define s2 iChannel0
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    vec3 dir = normalize(vec3(uv * 2.0 - 1.0, 1.0));
    vec2 dx = dFdx(uv), dy = dFdy(uv);
    float s = 0.0;
    { ivec2 r = textureSize(s2, 0); s += dot(vec2(r), vec2(1.0)); }
    { ivec3 r = textureSize(s3, 1); s += dot(vec3(r), vec3(1.0)); }
    { ivec2 r = textureSize(sc, 0); s += dot(vec2(r), vec2(1.0)); }
    { ivec3 r = textureSize(sa, 0); s += dot(vec3(r), vec3(1.0)); }
    { vec4 r = texture(s2, uv); s += dot(r, vec4(1.0)); }
    { vec4 r = texture(s3, vec3(uv, 0.5)); s += dot(r, vec4(1.0)); }
    { vec4 r = texture(sc, dir); s += dot(r, vec4(1.0)); }
    { vec4 r = texture(sa, vec3(uv, 1.0)); s += dot(r, vec4(1.0)); }
    { vec4 r = textureProj(s2, vec3(uv, 2.0)); s += dot(r, vec4(1.0)); }
    { vec4 r = textureProj(s2, vec4(uv, 0.0, 2.0)); s += dot(r, vec4(1.0)); }
    { vec4 r = textureProj(s3, vec4(uv, 0.5, 2.0)); s += dot(r, vec4(1.0)); }
    { vec4 r = textureOffset(s2, uv, ivec2(1, -1)); s += dot(r, vec4(1.0)); }
    { vec4 r = textureOffset(s3, vec3(uv, 0.5), ivec3(1, 0, -1)); s += dot(r, vec4(1.0)); }
    { vec4 r = textureOffset(sa, vec3(uv, 1.0), ivec2(-8, 7)); s += dot(r, vec4(1.0)); }
    { vec4 r = textureProjOffset(s2, vec3(uv, 2.0), ivec2(2)); s += dot(r, vec4(1.0)); }
    { vec4 r = textureProjOffset(s2, vec4(uv, 0.0, 2.0), ivec2(2)); s += dot(r, vec4(1.0)); }
    { vec4 r = textureProjOffset(s3, vec4(uv, 0.5, 2.0), ivec3(2)); s += dot(r, vec4(1.0)); }
    { vec4 r = texture(s2, uv, 0.5); s += dot(r, vec4(1.0)); }
    { vec4 r = texture(s3, vec3(uv, 0.5), 0.5); s += dot(r, vec4(1.0)); }
    { vec4 r = texture(sc, dir, 0.5); s += dot(r, vec4(1.0)); }
    { vec4 r = texture(sa, vec3(uv, 1.0), 0.5); s += dot(r, vec4(1.0)); }
    { vec4 r = textureProj(s2, vec3(uv, 2.0), 0.5); s += dot(r, vec4(1.0)); }
    { vec4 r = textureProj(s2, vec4(uv, 0.0, 2.0), 0.5); s += dot(r, vec4(1.0)); }
    { vec4 r = textureProj(s3, vec4(uv, 0.5, 2.0), 0.5); s += dot(r, vec4(1.0)); }
    { vec4 r = textureOffset(s2, uv, ivec2(1, -1), 0.5); s += dot(r, vec4(1.0)); }
    { vec4 r = textureOffset(s3, vec3(uv, 0.5), ivec3(1, 0, -1), 0.5); s += dot(r, vec4(1.0)); }
    { vec4 r = textureOffset(sa, vec3(uv, 1.0), ivec2(-8, 7), 0.5); s += dot(r, vec4(1.0)); }
    { vec4 r = textureProjOffset(s2, vec3(uv, 2.0), ivec2(2), 0.5); s += dot(r, vec4(1.0)); }
    { vec4 r = textureProjOffset(s2, vec4(uv, 0.0, 2.0), ivec2(2), 0.5); s += dot(r, vec4(1.0)); }
    { vec4 r = textureProjOffset(s3, vec4(uv, 0.5, 2.0), ivec3(2), 0.5); s += dot(r, vec4(1.0)); }
    { vec4 r = textureLod(s2, uv, 1.0); s += dot(r, vec4(1.0)); }
    { vec4 r = textureLod(s3, vec3(uv, 0.5), 1.0); s += dot(r, vec4(1.0)); }
    { vec4 r = textureLod(sc, dir, 1.0); s += dot(r, vec4(1.0)); }
    { vec4 r = textureLod(sa, vec3(uv, 1.0), 1.0); s += dot(r, vec4(1.0)); }
    { vec4 r = texelFetch(s2, ivec2(fragCoord), 0); s += dot(r, vec4(1.0)); }
    { vec4 r = texelFetch(s3, ivec3(fragCoord, 0), 0); s += dot(r, vec4(1.0)); }
    { vec4 r = texelFetch(sa, ivec3(fragCoord, 1), 0); s += dot(r, vec4(1.0)); }
    { vec4 r = texelFetchOffset(s2, ivec2(fragCoord), 0, ivec2(1)); s += dot(r, vec4(1.0)); }
    { vec4 r = texelFetchOffset(s3, ivec3(fragCoord, 0), 0, ivec3(1)); s += dot(r, vec4(1.0)); }
    { vec4 r = texelFetchOffset(sa, ivec3(fragCoord, 1), 0, ivec2(1)); s += dot(r, vec4(1.0)); }
    { vec4 r = textureLodOffset(s2, uv, 1.0, ivec2(1)); s += dot(r, vec4(1.0)); }
    { vec4 r = textureLodOffset(s3, vec3(uv, 0.5), 1.0, ivec3(1)); s += dot(r, vec4(1.0)); }
    { vec4 r = textureLodOffset(sa, vec3(uv, 1.0), 1.0, ivec2(1)); s += dot(r, vec4(1.0)); }
    { vec4 r = textureProjLod(s2, vec3(uv, 2.0), 1.0); s += dot(r, vec4(1.0)); }
    { vec4 r = textureProjLod(s2, vec4(uv, 0.0, 2.0), 1.0); s += dot(r, vec4(1.0)); }
    { vec4 r = textureProjLod(s3, vec4(uv, 0.5, 2.0), 1.0); s += dot(r, vec4(1.0)); }
    { vec4 r = textureProjLodOffset(s2, vec3(uv, 2.0), 1.0, ivec2(1)); s += dot(r, vec4(1.0)); }
    { vec4 r = textureProjLodOffset(s2, vec4(uv, 0.0, 2.0), 1.0, ivec2(1)); s += dot(r, vec4(1.0)); }
    { vec4 r = textureProjLodOffset(s3, vec4(uv, 0.5, 2.0), 1.0, ivec3(1)); s += dot(r, vec4(1.0)); }
    { vec4 r = textureGrad(s2, uv, dx, dy); s += dot(r, vec4(1.0)); }
    { vec4 r = textureGrad(s3, vec3(uv, 0.5), vec3(dx, 0.0), vec3(dy, 0.0)); s += dot(r, vec4(1.0)); }
    { vec4 r = textureGrad(sc, dir, vec3(dx, 0.0), vec3(dy, 0.0)); s += dot(r, vec4(1.0)); }
    { vec4 r = textureGrad(sa, vec3(uv, 1.0), dx, dy); s += dot(r, vec4(1.0)); }
    { vec4 r = textureGradOffset(s2, uv, dx, dy, ivec2(1)); s += dot(r, vec4(1.0)); }
    { vec4 r = textureGradOffset(s3, vec3(uv, 0.5), vec3(dx, 0.0), vec3(dy, 0.0), ivec3(1)); s += dot(r, vec4(1.0)); }
    { vec4 r = textureGradOffset(sa, vec3(uv, 1.0), dx, dy, ivec2(1)); s += dot(r, vec4(1.0)); }
    { vec4 r = textureProjGrad(s2, vec3(uv, 2.0), dx, dy); s += dot(r, vec4(1.0)); }
    { vec4 r = textureProjGrad(s2, vec4(uv, 0.0, 2.0), dx, dy); s += dot(r, vec4(1.0)); }
    { vec4 r = textureProjGrad(s3, vec4(uv, 0.5, 2.0), vec3(dx, 0.0), vec3(dy, 0.0)); s += dot(r, vec4(1.0)); }
    { vec4 r = textureProjGradOffset(s2, vec3(uv, 2.0), dx, dy, ivec2(1)); s += dot(r, vec4(1.0)); }
    { vec4 r = textureProjGradOffset(s2, vec4(uv, 0.0, 2.0), dx, dy, ivec2(1)); s += dot(r, vec4(1.0)); }
    { vec4 r = textureProjGradOffset(s3, vec4(uv, 0.5, 2.0), vec3(dx, 0.0), vec3(dy, 0.0), ivec3(1)); s += dot(r, vec4(1.0)); }
    fragColor = vec4(vec3(fract(s)), 1.0);
}
