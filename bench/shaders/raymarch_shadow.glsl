// Signed-distance ray march (96 steps) of a sphere, a rounded box and a blob smoothly joined over a plane: exercises loops with data-dependent exits, normals by central differences (6 scene evaluations), a 32-step soft shadow, diffuse/specular/sky lighting, fog and gamma.
const int kMarchSteps = 96;
const int kShadowSteps = 32;
const float kFar = 30.0;

float sdSphere(vec3 p, float r) { return length(p) - r; }

float sdRoundBox(vec3 p, vec3 halfSize, float radius) {
  vec3 q = abs(p) - halfSize + radius;
  return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0) - radius;
}

// A polynomial smooth minimum: the two surfaces melt into each other within `k` of their meeting.
float smoothUnion(float a, float b, float k) {
  float h = clamp(0.5 + 0.5 * (b - a) / k, 0.0, 1.0);
  return mix(b, a, h) - k * h * (1.0 - h);
}

// Distance to the scene; `material` says what was nearest (0 floor, 1 sphere, 2 box and blob).
float scene(vec3 p, out float material) {
  float floorDistance = p.y;
  float sphere = sdSphere(p - vec3(-1.2, 0.8, 0.3), 0.8);
  float box = sdRoundBox(p - vec3(1.1, 0.6, -0.2), vec3(0.6, 0.6, 0.6), 0.12);
  float blob = sdSphere(p - vec3(1.1, 1.3 + 0.2 * sin(iTime), -0.2), 0.45);
  float boxBlob = smoothUnion(box, blob, 0.35);
  float d = floorDistance;
  material = 0.0;
  if (sphere < d) { d = sphere; material = 1.0; }
  if (boxBlob < d) { d = boxBlob; material = 2.0; }
  return d;
}

float sceneDistance(vec3 p) {
  float unused;
  return scene(p, unused);
}

vec3 sceneNormal(vec3 p) {
  const float h = 0.001;
  return normalize(vec3(sceneDistance(p + vec3(h, 0, 0)) - sceneDistance(p - vec3(h, 0, 0)),
                        sceneDistance(p + vec3(0, h, 0)) - sceneDistance(p - vec3(0, h, 0)),
                        sceneDistance(p + vec3(0, 0, h)) - sceneDistance(p - vec3(0, 0, h))));
}

// Penumbra from the closest miss along the ray towards the light (1 lit, 0 in full shadow).
float softShadow(vec3 origin, vec3 towardLight) {
  float lit = 1.0;
  float t = 0.02;
  for (int i = 0; i < kShadowSteps; i++) {
    float d = sceneDistance(origin + towardLight * t);
    lit = min(lit, 10.0 * d / t);
    if (lit < 0.001) break;
    t += clamp(d, 0.02, 0.5);
  }
  return clamp(lit, 0.0, 1.0);
}

// Distance along the ray to the first surface, or -1.0; `material` of what was hit.
float march(vec3 origin, vec3 direction, out float material) {
  float t = 0.0;
  for (int i = 0; i < kMarchSteps; i++) {
    float d = scene(origin + direction * t, material);
    if (d < 0.0005 * t) return t;
    t += d;
    if (t > kFar) break;
  }
  return -1.0;
}

vec3 shade(vec3 p, vec3 rayDirection, float material) {
  vec3 n = sceneNormal(p);
  vec3 towardLight = normalize(vec3(-0.6, 0.8, 0.5));
  vec3 albedo = material < 0.5 ? vec3(0.45) * (0.7 + 0.3 * mod(floor(p.x) + floor(p.z), 2.0))
                : material < 1.5 ? vec3(0.85, 0.25, 0.15)
                                 : vec3(0.2, 0.5, 0.85);
  float diffuse = max(dot(n, towardLight), 0.0) * softShadow(p + n * 0.002, towardLight);
  float specular = pow(max(dot(reflect(rayDirection, n), towardLight), 0.0), 32.0);
  float sky = 0.5 + 0.5 * n.y;
  vec3 light = 1.2 * diffuse * vec3(1.0, 0.95, 0.85) + 0.25 * sky * vec3(0.5, 0.7, 1.0);
  return albedo * light + 0.4 * specular * diffuse;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
  vec3 eye = vec3(0.0, 2.2, 5.0);
  vec3 forward = normalize(vec3(0.0, 0.7, 0.0) - eye);
  vec3 right = normalize(cross(forward, vec3(0, 1, 0)));
  vec3 up = cross(right, forward);
  vec3 rayDirection = normalize(uv.x * right + uv.y * up + 1.8 * forward);

  vec3 skyColour = vec3(0.55, 0.7, 0.9) - 0.3 * rayDirection.y;
  vec3 col = skyColour;
  float material;
  float t = march(eye, rayDirection, material);
  if (t > 0.0) {
    col = shade(eye + rayDirection * t, rayDirection, material);
    col = mix(col, skyColour, 1.0 - exp(-0.004 * t * t));  // fog
  }
  fragColor = vec4(pow(col, vec3(0.4545)), 1.0);
}
