// A swirl-warped, repeating texture with a blur strip and a texel inset: exercises texture() with implicit LOD (the warp's derivatives choose the mip level), textureLod at chosen levels, texelFetch, textureSize and iChannelResolution.

// The inset (top-right) shows the image's top-left 64x64 texels, each drawn as a 2x2 square.
const float kInsetScale = 2.0;
const int kInsetTexels = 64;

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec2 uv = fragCoord / iResolution.xy;
  vec2 centred = (fragCoord - 0.5 * iResolution.xy) / iResolution.y;
  float r = length(centred);

  // The swirl: a rotation that grows towards the centre; the texture also repeats more densely towards
  // the edges, so that the corners are minified several levels (texture() must pick a coarser mip).
  float angle = 3.0 * smoothstep(0.7, 0.0, r) + 0.3 * iTime;
  mat2 turn = mat2(cos(angle), sin(angle), -sin(angle), cos(angle));
  vec2 warped = turn * centred * (1.2 + 8.0 * r * r) + 0.5;
  // Every sample is taken outside any branch: derivatives (implicit LOD) are undefined in non-uniform
  // control flow.
  vec3 swirl = texture(iChannel0, warped).rgb;

  // Bottom strip: the unwarped image at mip level 0 on the left to level 6 on the right.
  vec3 blurred = textureLod(iChannel0, vec2(uv.x * 2.0, uv.y * 8.0), 6.0 * uv.x).rgb;

  // Top-right inset: exact texels, no filtering. Texel row 0 is the image's bottom row (the image is
  // uploaded flipped, as ShaderToy does), so the image's top rows are the last ones.
  ivec2 size = textureSize(iChannel0, 0);
  vec2 insetSize = vec2(float(kInsetTexels) * kInsetScale);
  vec2 insetOrigin = iResolution.xy - insetSize - 8.0;
  ivec2 texel = ivec2(floor((fragCoord - insetOrigin) / kInsetScale)) + ivec2(0, size.y - kInsetTexels);
  vec3 exact = texelFetch(iChannel0, clamp(texel, ivec2(0), max(size - 1, ivec2(0))), 0).rgb;

  vec3 col = swirl * (1.0 - 0.3 * smoothstep(0.3, 0.9, r));
  if (uv.y < 0.125) col = blurred;
  vec2 inInset = fragCoord - insetOrigin;
  if (all(greaterThanEqual(inInset, vec2(0.0))) && all(lessThan(inInset, insetSize))) col = exact;
  // A frame round the inset, and a line at the strip's edge; iChannelResolution tints the frame (white
  // when the channel is a 256x256 image).
  vec2 outside = max(-inInset, inInset - insetSize);
  if (max(outside.x, outside.y) > 0.0 && max(outside.x, outside.y) < 3.0)
    col = iChannelResolution[0].xyx / 256.0;
  if (abs(uv.y - 0.125) * iResolution.y < 1.5) col = vec3(1.0);
  fragColor = vec4(col, 1.0);
}
