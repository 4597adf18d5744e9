// exercises: the texture calls ShaderToy programs make on iChannel0..3: bias, lod, offsets (constant expressions), fetches, sizes
const ivec2 OFFSET = ivec2(-1, 2);
vec4 sampleAt(sampler2D channel, vec2 uv) {
    return texture(channel, uv);
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    vec4 c = sampleAt(iChannel0, uv);
    c += texture(iChannel1, uv, -1.0);
    c += textureLod(iChannel2, uv, 2.0);
    c += textureOffset(iChannel3, uv, OFFSET);
    c += textureOffset(iChannel3, uv, ivec2(gl_MaxProgramTexelOffset, gl_MinProgramTexelOffset));
    c += texelFetch(iChannel0, ivec2(fragCoord) % textureSize(iChannel0, 0), 0);
    c += texelFetchOffset(iChannel0, ivec2(fragCoord), 0, OFFSET * 2);
    c += textureGrad(iChannel1, uv, dFdx(uv), dFdy(uv));
    c += textureProj(iChannel2, vec3(uv, 1.0));
    c.rgb += texture(iChannel0, uv / iChannelResolution[0].xy).rgb;
    fragColor = c / 10.0;
}
