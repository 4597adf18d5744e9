// Voronoi cells with a distance-to-border outline: exercises nested 3x3 and 5x5 loops over integer cell offsets, an int hash, vector min/compare bookkeeping, normalize/dot for the exact border distance.

// A point in [0, 1)^2 per cell: an integer hash of the cell (multiplications by odd constants and
// xor-shifts), the cell kept non-negative because negative int to uint is undefined in GLSL ES.
vec2 cellPoint(ivec2 cell) {
  uvec2 q = uvec2(cell + 1024) * uvec2(1597334677u, 3812015801u);
  uint h = (q.x ^ q.y) * 1597334677u;
  h ^= h >> 16u;
  uvec2 both = uvec2(h, h * 2654435769u);
  return vec2(both >> 8u) / 16777216.0;
}

// The cell's point, swaying a little with time.
vec2 featurePoint(ivec2 cell) {
  vec2 r = cellPoint(cell);
  return 0.5 + 0.4 * sin(iTime + 6.2831853 * r);
}

// x: distance to the border of the cell p is in (not to its point: to the perpendicular bisector with the
// nearest other point); yz: that cell's id hash.
vec3 voronoi(vec2 p) {
  ivec2 cell = ivec2(floor(p));
  vec2 f = fract(p);
  // First pass: the nearest point, in the 3x3 block around p's cell.
  ivec2 nearestCell = ivec2(0);
  vec2 toNearest = vec2(0.0);
  float best = 8.0;
  for (int j = -1; j <= 1; j++)
    for (int i = -1; i <= 1; i++) {
      ivec2 offset = ivec2(i, j);
      vec2 r = vec2(offset) + featurePoint(cell + offset) - f;
      float d = dot(r, r);
      if (d < best) {
        best = d;
        toNearest = r;
        nearestCell = offset;
      }
    }
  // Second pass: the distance to each bisector between the nearest point and its neighbours (5x5 around
  // the nearest cell, so that every neighbour that can share a border is seen).
  float border = 8.0;
  for (int j = -2; j <= 2; j++)
    for (int i = -2; i <= 2; i++) {
      ivec2 offset = nearestCell + ivec2(i, j);
      vec2 r = vec2(offset) + featurePoint(cell + offset) - f;
      vec2 between = r - toNearest;
      if (dot(between, between) > 1e-5) border = min(border, dot(0.5 * (toNearest + r), normalize(between)));
    }
  return vec3(border, cellPoint(cell + nearestCell));
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec2 p = 7.0 * fragCoord / iResolution.y;
  vec3 v = voronoi(p);
  vec3 fill = 0.55 + 0.45 * cos(6.2831853 * (v.y + vec3(0.0, 0.33, 0.67)));
  fill *= 0.75 + 0.25 * v.z;
  vec3 col = fill * (0.55 + 0.45 * smoothstep(0.0, 0.3, v.x));   // darker towards the border
  col = mix(vec3(0.05), col, smoothstep(0.015, 0.035, v.x));       // the outline
  col += 0.2 * (1.0 - smoothstep(0.0, 0.015, abs(v.x - 0.12)));  // an inner contour line
  fragColor = vec4(col, 1.0);
}
