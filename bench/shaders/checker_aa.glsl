// Anti-aliased checkerboard in a rotated domain whose scale grows towards the edges: exercises fwidth (screen-space derivatives), mat2 rotation, clamp-filtered square waves.

// A square wave of period 1 (+1 on one half, -1 on the other) blurred over `w`, the width of a pixel in
// the same units: the signed distance to the nearest edge, divided by the pixel's half-width, clamped.
float filteredSquare(float x, float w) {
  float edgeDistance = abs(fract(x + 0.25) - 0.5) - 0.25;  // -0.25 .. 0.25, zero on the edges
  return clamp(edgeDistance / max(0.5 * w, 1e-6), -1.0, 1.0);
}

// 1 on one colour of squares, 0 on the other, with grey where a pixel straddles an edge.
float checker(vec2 p) {
  vec2 w = fwidth(p);
  return 0.5 + 0.5 * filteredSquare(p.x, w.x) * filteredSquare(p.y, w.y);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec2 uv = (fragCoord - 0.5 * iResolution.xy) / iResolution.y;
  float angle = 0.45 + 0.1 * iTime;
  mat2 rotation = mat2(cos(angle), sin(angle), -sin(angle), cos(angle));
  // The squares shrink away from the centre, down to a few pixels in the corners, where an unfiltered
  // checkerboard would shimmer into moire.
  float scale = 6.0 + 120.0 * dot(uv, uv);
  vec2 p = rotation * uv * scale;
  float c = checker(p);
  vec3 light = vec3(0.95, 0.85, 0.6), dark = vec3(0.1, 0.2, 0.35);
  vec3 col = mix(dark, light, c);
  col *= 1.0 - 0.35 * dot(uv, uv);  // vignette
  fragColor = vec4(col, 1.0);
}
