// exercises: 8.8 every texture lookup overload for isampler2D, isampler3D, isamplerCube, isampler2DArray (int results)
precision highp isampler2D;
precision highp isampler3D;
precision highp isamplerCube;
precision highp isampler2DArray;
uniform isampler2D is2;
uniform isampler3D is3;
uniform isamplerCube isc;
uniform isampler2DArray isa;

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    vec3 dir = normalize(vec3(uv * 2.0 - 1.0, 1.0));
    vec2 dx = dFdx(uv), dy = dFdy(uv);
    float s = 0.0;
    { ivec2 r = textureSize(is2, 0); s += dot(vec2(r), vec2(1.0)); }
    { ivec3 r = textureSize(is3, 1); s += dot(vec3(r), vec3(1.0)); }
    { ivec2 r = textureSize(isc, 0); s += dot(vec2(r), vec2(1.0)); }
    { ivec3 r = textureSize(isa, 0); s += dot(vec3(r), vec3(1.0)); }
    { ivec4 r = texture(is2, uv); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = texture(is3, vec3(uv, 0.5)); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = texture(isc, dir); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = texture(isa, vec3(uv, 1.0)); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureProj(is2, vec3(uv, 2.0)); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureProj(is2, vec4(uv, 0.0, 2.0)); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureProj(is3, vec4(uv, 0.5, 2.0)); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureOffset(is2, uv, ivec2(1, -1)); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureOffset(is3, vec3(uv, 0.5), ivec3(1, 0, -1)); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureOffset(isa, vec3(uv, 1.0), ivec2(-8, 7)); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureProjOffset(is2, vec3(uv, 2.0), ivec2(2)); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureProjOffset(is2, vec4(uv, 0.0, 2.0), ivec2(2)); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureProjOffset(is3, vec4(uv, 0.5, 2.0), ivec3(2)); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = texture(is2, uv, 0.5); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = texture(is3, vec3(uv, 0.5), 0.5); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = texture(isc, dir, 0.5); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = texture(isa, vec3(uv, 1.0), 0.5); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureProj(is2, vec3(uv, 2.0), 0.5); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureProj(is2, vec4(uv, 0.0, 2.0), 0.5); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureProj(is3, vec4(uv, 0.5, 2.0), 0.5); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureOffset(is2, uv, ivec2(1, -1), 0.5); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureOffset(is3, vec3(uv, 0.5), ivec3(1, 0, -1), 0.5); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureOffset(isa, vec3(uv, 1.0), ivec2(-8, 7), 0.5); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureProjOffset(is2, vec3(uv, 2.0), ivec2(2), 0.5); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureProjOffset(is2, vec4(uv, 0.0, 2.0), ivec2(2), 0.5); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureProjOffset(is3, vec4(uv, 0.5, 2.0), ivec3(2), 0.5); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureLod(is2, uv, 1.0); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureLod(is3, vec3(uv, 0.5), 1.0); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureLod(isc, dir, 1.0); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureLod(isa, vec3(uv, 1.0), 1.0); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = texelFetch(is2, ivec2(fragCoord), 0); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = texelFetch(is3, ivec3(fragCoord, 0), 0); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = texelFetch(isa, ivec3(fragCoord, 1), 0); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = texelFetchOffset(is2, ivec2(fragCoord), 0, ivec2(1)); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = texelFetchOffset(is3, ivec3(fragCoord, 0), 0, ivec3(1)); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = texelFetchOffset(isa, ivec3(fragCoord, 1), 0, ivec2(1)); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureLodOffset(is2, uv, 1.0, ivec2(1)); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureLodOffset(is3, vec3(uv, 0.5), 1.0, ivec3(1)); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureLodOffset(isa, vec3(uv, 1.0), 1.0, ivec2(1)); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureProjLod(is2, vec3(uv, 2.0), 1.0); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureProjLod(is2, vec4(uv, 0.0, 2.0), 1.0); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureProjLod(is3, vec4(uv, 0.5, 2.0), 1.0); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureProjLodOffset(is2, vec3(uv, 2.0), 1.0, ivec2(1)); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureProjLodOffset(is2, vec4(uv, 0.0, 2.0), 1.0, ivec2(1)); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureProjLodOffset(is3, vec4(uv, 0.5, 2.0), 1.0, ivec3(1)); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureGrad(is2, uv, dx, dy); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureGrad(is3, vec3(uv, 0.5), vec3(dx, 0.0), vec3(dy, 0.0)); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureGrad(isc, dir, vec3(dx, 0.0), vec3(dy, 0.0)); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureGrad(isa, vec3(uv, 1.0), dx, dy); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureGradOffset(is2, uv, dx, dy, ivec2(1)); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureGradOffset(is3, vec3(uv, 0.5), vec3(dx, 0.0), vec3(dy, 0.0), ivec3(1)); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureGradOffset(isa, vec3(uv, 1.0), dx, dy, ivec2(1)); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureProjGrad(is2, vec3(uv, 2.0), dx, dy); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureProjGrad(is2, vec4(uv, 0.0, 2.0), dx, dy); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureProjGrad(is3, vec4(uv, 0.5, 2.0), vec3(dx, 0.0), vec3(dy, 0.0)); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureProjGradOffset(is2, vec3(uv, 2.0), dx, dy, ivec2(1)); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureProjGradOffset(is2, vec4(uv, 0.0, 2.0), dx, dy, ivec2(1)); s += dot(vec4(r), vec4(1.0)); }
    { ivec4 r = textureProjGradOffset(is3, vec4(uv, 0.5, 2.0), vec3(dx, 0.0), vec3(dy, 0.0), ivec3(1)); s += dot(vec4(r), vec4(1.0)); }
    fragColor = vec4(vec3(fract(s)), 1.0);
}
