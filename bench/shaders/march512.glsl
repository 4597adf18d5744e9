// A heavy signed-distance ray march (up to 512 under-relaxed steps, meant for 1024x1024) down an endless colonnade of twisted pillars and rings over a rippled floor: exercises long data-dependent loops, domain repetition (mod/floor), per-cell variation, 6-sample normals, a 32-step soft shadow, 5-sample ambient occlusion and fog.
const int kMarchSteps = 512;
const int kShadowSteps = 32;
const float kFar = 90.0;
const float kCell = 4.0;

float sdRoundBox(vec3 p, vec3 halfSize, float radius) {
  vec3 q = abs(p) - halfSize + radius;
  return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0) - radius;
}

float sdTorus(vec3 p, vec2 radii) { return length(vec2(length(p.xz) - radii.x, p.y)) - radii.y; }

mat2 rotation(float a) { return mat2(cos(a), sin(a), -sin(a), cos(a)); }

// A number per cell, for each pillar's height and colour.
float cellValue(vec2 id) { return 0.5 + 0.5 * sin(id.x * 1.7 + id.y * 2.3 + 0.4 * id.x * id.y); }

// Distance to the scene; `material`: 0 the floor, otherwise 1 + the cell's value (pillars and rings).
float scene(vec3 p, out float material) {
  float floorDistance = p.y - 0.08 * sin(1.3 * p.x) * sin(1.1 * p.z);
  vec2 id = floor(p.xz / kCell + 0.5);
  vec3 q = vec3(p.x - id.x * kCell, p.y, p.z - id.y * kCell);  // the position within its cell
  float v = cellValue(id);
  float height = 1.2 + 1.4 * v;
  vec3 twisted = q - vec3(0.0, height, 0.0);
  twisted.xz = rotation(0.6 * q.y + 0.3 * iTime) * twisted.xz;
  float pillar = sdRoundBox(twisted, vec3(0.35, height, 0.35), 0.08);
  float ring = sdTorus(q - vec3(0.0, 2.0 * height + 0.35, 0.0), vec2(0.65, 0.12));
  // Twisting stretches space and the neighbouring cells are not looked at: both are made up for by the
  // march's under-relaxed step.
  float solid = min(pillar, ring);
  material = solid < floorDistance ? 1.0 + v : 0.0;
  return min(solid, floorDistance);
}

float sceneDistance(vec3 p) {
  float unused;
  return scene(p, unused);
}

vec3 sceneNormal(vec3 p) {
  const float h = 0.0015;
  return normalize(vec3(sceneDistance(p + vec3(h, 0, 0)) - sceneDistance(p - vec3(h, 0, 0)),
                        sceneDistance(p + vec3(0, h, 0)) - sceneDistance(p - vec3(0, h, 0)),
                        sceneDistance(p + vec3(0, 0, h)) - sceneDistance(p - vec3(0, 0, h))));
}

float softShadow(vec3 origin, vec3 towardLight) {
  float lit = 1.0;
  float t = 0.03;
  for (int i = 0; i < kShadowSteps; i++) {
    float d = sceneDistance(origin + towardLight * t);
    lit = min(lit, 8.0 * d / t);
    if (lit < 0.001 || t > 20.0) break;
    t += clamp(d, 0.05, 1.0);
  }
  return clamp(lit, 0.0, 1.0);
}

// Darkening where the scene closes in around the normal: five probes outwards.
float ambientOcclusion(vec3 p, vec3 n) {
  float occlusion = 0.0, weight = 1.0;
  for (int i = 1; i <= 5; i++) {
    float h = 0.06 * float(i);
    occlusion += weight * (h - sceneDistance(p + n * h));
    weight *= 0.7;
  }
  return clamp(1.0 - 2.5 * occlusion, 0.0, 1.0);
}

float march(vec3 origin, vec3 direction, out float material) {
  float t = 0.0;
  for (int i = 0; i < kMarchSteps; i++) {
    float d = scene(origin + direction * t, material);
    if (abs(d) < 0.0004 * t) return t;
    t += 0.55 * d;
    if (t > kFar) break;
  }
  return -1.0;
}

vec3 shade(vec3 p, vec3 rayDirection, float material) {
  vec3 n = sceneNormal(p);
  vec3 towardLight = normalize(vec3(0.5, 0.7, 0.35));
  vec3 albedo = material < 0.5 ? vec3(0.5, 0.45, 0.4) * (0.8 + 0.2 * sin(3.0 * p.x) * sin(3.0 * p.z))
                               : 0.5 + 0.45 * cos(6.2831853 * (material + vec3(0.0, 0.3, 0.55)));
  float diffuse = max(dot(n, towardLight), 0.0) * softShadow(p + n * 0.003, towardLight);
  float specular = pow(max(dot(reflect(rayDirection, n), towardLight), 0.0), 24.0);
  float ao = ambientOcclusion(p, n);
  vec3 light = 1.3 * diffuse * vec3(1.0, 0.9, 0.75) + 0.35 * ao * (0.5 + 0.5 * n.y) * vec3(0.45, 0.6, 0.9);
  return albedo * light + 0.3 * specular * diffuse;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
  // Between two rows of pillars, looking down the colonnade and a little across it.
  vec3 eye = vec3(2.0, 1.5, -1.0 + iTime);
  vec3 target = eye + vec3(0.35, -0.12, 1.0);
  vec3 forward = normalize(target - eye);
  vec3 right = normalize(cross(forward, vec3(0, 1, 0)));
  vec3 up = cross(right, forward);
  vec3 rayDirection = normalize(uv.x * right + uv.y * up + 1.6 * forward);

  vec3 skyColour = mix(vec3(0.85, 0.75, 0.65), vec3(0.35, 0.5, 0.8), clamp(rayDirection.y * 2.5, 0.0, 1.0));
  vec3 col = skyColour;
  float material;
  float t = march(eye, rayDirection, material);
  if (t > 0.0) {
    col = shade(eye + rayDirection * t, rayDirection, material);
    col = mix(col, skyColour, 1.0 - exp(-0.0006 * t * t));
  }
  fragColor = vec4(pow(col, vec3(0.4545)), 1.0);
}
