// Smooth-coloured Mandelbrot set: exercises a float loop of up to 256 iterations left early by `break`, log2-based continuous iteration counts, a cosine palette.
const int kMaxIterations = 256;
const float kEscapeRadius = 256.0;  // large, so that the smooth count below is smooth

vec3 palette(float t) {
  return 0.5 + 0.5 * cos(6.2831853 * (vec3(0.0, 0.15, 0.3) + t));
}

// The continuous escape count of c (the integer count corrected by how far past the radius z went), or
// -1.0 for a point that never escaped (inside the set, as far as we can tell).
float escapeCount(vec2 c) {
  vec2 z = vec2(0.0);
  float n = 0.0;
  bool escaped = false;
  for (int i = 0; i < kMaxIterations; i++) {
    z = vec2(z.x * z.x - z.y * z.y, 2.0 * z.x * z.y) + c;
    if (dot(z, z) > kEscapeRadius * kEscapeRadius) {
      escaped = true;
      break;
    }
    n += 1.0;
  }
  if (!escaped) return -1.0;
  // log2(log2(|z|^2)) is log2(log2(R^2)) = 4 for R = 256 when |z| = R.
  return n - log2(log2(dot(z, z))) + 4.0;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
  // The whole set, slightly to the left of centre; iTime zooms into the seahorse valley.
  float zoom = exp(-0.2 * iTime);
  vec2 centre = mix(vec2(-0.745, 0.11), vec2(-0.6, 0.0), zoom);
  vec2 c = centre + uv * 1.25 * zoom;
  float n = escapeCount(c);
  vec3 col = n < 0.0 ? vec3(0.02, 0.01, 0.05) : palette(0.03 * n + 0.55) * (1.0 - exp(-0.15 * n));
  fragColor = vec4(col, 1.0);
}
