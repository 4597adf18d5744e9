// Domain-warped value-noise fbm (6 octaves, 3 fbm per pixel) on an integer hash: exercises uint multiplications, xor-shifts, floatBitsToUint / uintBitsToFloat, ivec/uvec conversions, quintic interpolation.
const int kOctaves = 6;

// A 32-bit integer mix (a PCG-style step: multiply-add, a data-dependent shift, multiply, xor-shift).
uint mixBits(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

// A number in [0, 1) for a lattice point and a seed: the hash's top 23 bits as the mantissa of a float
// in [1, 2). The cell coordinates are kept non-negative (the picture never reaches x or y below -4096),
// because converting a negative int to uint is left undefined by GLSL ES.
float latticeValue(ivec2 cell, uint seed) {
  uvec2 u = uvec2(cell + 4096);
  uint h = mixBits(u.x ^ mixBits(u.y ^ mixBits(seed)));
  return uintBitsToFloat(0x3f800000u | (h >> 9u)) - 1.0;
}

// Value noise: the four corners' values blended with a C2 (quintic) fade.
float valueNoise(vec2 p, uint seed) {
  ivec2 cell = ivec2(floor(p));
  vec2 f = fract(p);
  vec2 fade = f * f * f * (f * (f * 6.0 - 15.0) + 10.0);
  float a = latticeValue(cell, seed);
  float b = latticeValue(cell + ivec2(1, 0), seed);
  float c = latticeValue(cell + ivec2(0, 1), seed);
  float d = latticeValue(cell + ivec2(1, 1), seed);
  return mix(mix(a, b, fade.x), mix(c, d, fade.x), fade.y);
}

// Fractal sum: each octave twice the frequency, half the amplitude, rotated, with its own seed (the bits
// of its frequency, so that no two octaves share a lattice).
float fbm(vec2 p, uint seed) {
  const mat2 turn = mat2(0.8, 0.6, -0.6, 0.8);
  float sum = 0.0, amplitude = 0.5, frequency = 1.0;
  for (int i = 0; i < kOctaves; i++) {
    sum += amplitude * valueNoise(p, seed ^ floatBitsToUint(frequency));
    p = turn * p * 2.0 + vec2(17.0, 9.0);
    amplitude *= 0.5;
    frequency *= 2.0;
  }
  return sum / (1.0 - 2.0 * amplitude);  // the amplitudes summed to 1 - 2 * the next one
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec2 p = 4.0 * fragCoord / iResolution.y;
  // Two fbms displace the lookup of a third: marbled, cloud-like bands.
  vec2 warp = vec2(fbm(p + vec2(0.0, 0.1 * iTime), 1u), fbm(p + vec2(5.2, 1.3), 2u));
  float f = fbm(p + 3.0 * warp, 3u);
  vec3 col = mix(vec3(0.08, 0.12, 0.3), vec3(0.95, 0.65, 0.3), smoothstep(0.3, 0.75, f));
  col = mix(col, vec3(0.2, 0.7, 0.6), 0.6 * smoothstep(0.55, 0.9, warp.y));
  col *= 0.6 + 0.6 * f;
  fragColor = vec4(col, 1.0);
}
