// ShaderToy's default new-shader program (a uv gradient cycling with iTime): exercises the minimum, one cos of a vector.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  // Pixel coordinates from 0 to 1.
  vec2 uv = fragCoord / iResolution.xy;
  // Colour that moves with time.
  vec3 col = 0.5 + 0.5 * cos(iTime + uv.xyx + vec3(0, 2, 4));
  fragColor = vec4(col, 1.0);
}
