// Layers of noise and stars on the classic fract(sin(dot(p, vec2(12.9898, 78.233))) * 43758.5453) hash: exercises sin of large arguments (whose low bits implementations round differently), fract, floor, smoothstep.

// The classic one-line hash: a number in [0, 1) for a point. Its value depends on the low bits of
// sin(x) * 43758.5453 for x up to a few thousand, so it is a test of sin's accuracy too.
float hash(vec2 p) {
  return fract(sin(dot(p, vec2(12.9898, 78.233))) * 43758.5453);
}

// Value noise on that hash (smoothstep-blended corners).
float noise(vec2 p) {
  vec2 i = floor(p), f = fract(p);
  vec2 u = f * f * (3.0 - 2.0 * f);
  float bottom = mix(hash(i), hash(i + vec2(1, 0)), u.x);
  float top = mix(hash(i + vec2(0, 1)), hash(i + vec2(1, 1)), u.x);
  return mix(bottom, top, u.y);
}

// A field of stars: one per cell at a hashed position, with a hashed brightness; most cells stay dark.
float stars(vec2 p, float density) {
  vec2 cell = floor(p);
  float h = hash(cell);
  if (h > density) return 0.0;
  vec2 at = vec2(hash(cell + 31.7), hash(cell + 67.1));
  float d = length(fract(p) - at);
  return smoothstep(0.08, 0.0, d) * (0.4 + 0.6 * hash(cell + 3.3));
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec2 uv = fragCoord / iResolution.y;
  // Four octaves of nebula, each drifting at its own speed.
  float nebula = 0.0, amplitude = 0.55;
  vec2 p = uv * 3.0;
  for (int i = 0; i < 4; i++) {
    nebula += amplitude * noise(p + float(i) * vec2(1.7, 9.2) + 0.05 * iTime);
    p *= 2.1;
    amplitude *= 0.5;
  }
  vec3 col = mix(vec3(0.02, 0.0, 0.08), vec3(0.55, 0.15, 0.45), smoothstep(0.35, 0.85, nebula));
  col += vec3(0.1, 0.3, 0.5) * smoothstep(0.6, 1.0, noise(uv * 5.0 + 40.0));
  // Three star layers: big and rare, then smaller and denser.
  col += vec3(1.0, 0.9, 0.7) * stars(uv * 12.0, 0.25);
  col += vec3(0.8, 0.9, 1.0) * stars(uv * 30.0 + 11.0, 0.35);
  col += vec3(0.7) * stars(uv * 70.0 + 23.0, 0.5);
  // The raw hash, visible as a grainy strip along the bottom.
  if (uv.y < 0.06) col = mix(col, vec3(hash(floor(fragCoord / 4.0))), 0.8);
  fragColor = vec4(col, 1.0);
}
