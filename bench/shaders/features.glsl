// Every GLSL ES 3.00 language feature in one picture: eight bands, bottom to top drawn by structs and arrays, integer bits, a fallthrough switch, loops, matrices, vector relations, parameters and operators, the preprocessor; a magenta band means a feature computed a wrong value.

// ---- The preprocessor: object-like and function-like macros, #if / #elif / #else / #endif, #ifdef,
// #ifndef, defined with and without parentheses, #undef, and an #error in a group that must be skipped.
#define BANDS 8
#define SQUARE(x) ((x) * (x))
#define LERP3(a, b, t) mix((a), (b), clamp((t), 0.0, 1.0))
#define LEVEL 2
#if LEVEL > 2
#define STRIPES 16
#elif LEVEL == 2 && defined(BANDS)
#define STRIPES 12
#else
#define STRIPES 4
#endif
#ifdef SQUARE
#define CURVE(x) SQUARE(x)
#else
#define CURVE(x) (x)
#endif
#ifndef NOT_DEFINED_ANYWHERE
#define TEMPORARY 1
#endif
#if defined TEMPORARY && !defined(NOT_DEFINED_ANYWHERE)
#undef TEMPORARY
#endif
#ifdef TEMPORARY
#error TEMPORARY was not undefined
#endif

const vec3 kWrong = vec3(1.0, 0.0, 1.0);  // the colour of a failed check

// ---- Structs holding arrays, nested structs, const arrays, a global variable.
struct ColorStop {
  float at;
  vec3 color;
};

struct Gradient {
  ColorStop stops[4];
  int count;
};

const float kWeights[4] = float[4](0.1, 0.2, 0.3, 0.4);
const ivec3 kOffsets = ivec3(1, 2, 3);
int gCalls = 0;  // a global that functions write (a side effect the caller can see)

// ---- Overloads: the same name on different parameter types.
float luma(const in vec3 c) { return dot(c, vec3(0.299, 0.587, 0.114)); }
float luma(vec4 c) { return luma(c.rgb) * c.a; }
int twice(int v) { return v * 2; }
float twice(float v) { return v * 2.0; }
vec3 twice(vec3 v) { return v + v; }

// ---- Band 0: a gradient stored as an array of structs in a struct; array constructors, .length(), arrays
// as parameters and return values, struct and array equality, early return.
Gradient sunset() {
  Gradient g;
  g.stops = ColorStop[4](ColorStop(0.0, vec3(0.1, 0.05, 0.3)), ColorStop(0.35, vec3(0.8, 0.2, 0.4)),
                         ColorStop(0.7, vec3(1.0, 0.6, 0.2)), ColorStop(1.0, vec3(1.0, 0.95, 0.7)));
  g.count = g.stops.length();
  return g;
}

vec3 evaluate(Gradient g, float t) {
  if (t <= g.stops[0].at) return g.stops[0].color;
  for (int i = 1; i < g.count; ++i) {
    if (t <= g.stops[i].at) {
      ColorStop a = g.stops[i - 1], b = g.stops[i];
      return mix(a.color, b.color, (t - a.at) / (b.at - a.at));
    }
  }
  return g.stops[g.count - 1].color;
}

float[3] channels(vec3 c) { return float[3](c.r, c.g, c.b); }

float total(float values[3]) {
  float sum = 0.0;
  for (int i = 0; i < values.length(); i++) sum += values[i];
  return sum;
}

vec3 gradientBand(vec2 p) {
  Gradient g = sunset();
  Gradient copy = g;
  copy.stops[2].color = vec3(0.2, 0.8, 0.6);  // a write into an array inside a struct
  float implicit[] = float[](0.25, 0.5, 0.25);  // size from the constructor
  bool ok = copy != g && copy.stops[1] == g.stops[1] && channels(vec3(0.25, 0.5, 0.25)) == implicit &&
            total(implicit) == 1.0 && g.count == 4 && implicit.length() == 3;
  if (!ok) return kWrong;
  // Upper half the gradient, lower half its copy with the changed stop.
  if (p.y > 0.5) return evaluate(g, p.x);
  return evaluate(copy, p.x);
}

// ---- Band 1: integer arithmetic and bits: ^ & | ~ << >> % / on int, ivec and uint, wrapping uint products.
vec3 bitsBand(ivec2 q) {
  int x = q.x >> 2, y = q.y >> 1;
  int pattern = (x ^ y) & 31;
  int rings = (x | y << 2) % 9;
  int parts = x / 3 + kOffsets.y * (y / 5);
  int negative = ~x >> 3;  // ~x is -x - 1; a signed right shift keeps the sign
  uint u = uint(pattern) * 2654435761u + uint(parts);
  u ^= u >> 13u;
  u = (u << 3u) | (u >> 29u);  // rotate left by 3
  uvec2 pair = uvec2(u, u * 7u) % uvec2(256u, 128u);
  ivec2 grid = ivec2(x, y) * 3 - ivec2(1) + kOffsets.xy;
  if (negative >= 0 || -negative != x / 8 + 1 || grid.x != 3 * x || twice(-7) != -14) return kWrong;
  return vec3(float(pattern) / 31.0, 0.6 * float(pair.x) / 255.0 + 0.4 * float(rings) / 8.0,
              float(-negative % 16) / 15.0);
}

// ---- Band 2: switch with fallthrough, two labels on one body, default.
vec3 switchBand(vec2 p) {
  int cell = int(p.x * float(STRIPES));
  vec3 c = vec3(0.0);
  switch (cell % 6) {
    case 0:
      c.r = 1.0;  // falls through: red and green, yellow
    case 1:
      c.g = 0.8;
      break;
    case 2:
    case 3:
      c.b = 1.0;
      c.r = cell % 6 == 2 ? 0.5 : 0.0;
      break;
    default:
      c = vec3(0.45);
      break;
  }
  return c * (0.7 + 0.3 * p.y);
}

// ---- Band 3: loops: while with break, for with continue, do-while; bars of integer sequences.
int collatzSteps(int n) {
  int steps = 0;
  while (n != 1) {
    n = n % 2 == 0 ? n / 2 : 3 * n + 1;
    if (++steps >= 200) break;
  }
  return steps;
}

int divisorCount(int n) {
  int count = 0;
  for (int d = 1; d <= n; d++) {
    if (n % d != 0) continue;
    count++;
  }
  return count;
}

int digitSum(int n) {
  int sum = 0;
  do {
    sum += n % 10;
    n /= 10;
  } while (n > 0);
  return sum;
}

vec3 loopBand(vec2 p) {
  float column = p.x * 64.0;
  int n = int(column) + 1;
  if (collatzSteps(27) != 111 || divisorCount(60) != 12 || digitSum(1234) != 10) return kWrong;
  if (fract(column) < 0.2) return vec3(0.05);  // the gap between bars
  float height = float(collatzSteps(n)) / 115.0;
  vec3 bar = vec3(float(divisorCount(n)) / 12.0, float(digitSum(n)) / 13.0, 0.7);
  return p.y < height ? bar : vec3(0.1, 0.1, 0.12);
}

// ---- Band 4: matrices: square and non-square constructors, mat*vec, vec*mat, mat*mat, transpose,
// inverse, determinant, outerProduct, matrixCompMult, columns and elements, truncating constructors.
vec3 matrixBand(vec2 pixel, vec2 size) {
  float a = 0.6 + 0.2 * iTime;
  mat2 turn = mat2(cos(a), sin(a), -sin(a), cos(a));
  vec2 q = turn * (pixel - 0.5 * size) / 12.0;
  mat3x2 spread = mat3x2(vec2(1.0, 0.0), vec2(0.0, 1.0), vec2(0.5));  // three columns of two rows
  mat2x3 lift = transpose(spread);
  vec3 c = lift * fract(q) * 0.8;  // mat2x3 * vec2: a vec3
  vec2 back = c * lift;            // vec3 * mat2x3: a row vector times the matrix, a vec2
  mat3 square = lift * spread;     // (3x2) times (2x3): a 3x3
  mat3 yiq = mat3(0.299, 0.596, 0.211, 0.587, -0.274, -0.523, 0.114, -0.322, 0.312);
  vec3 roundTrip = inverse(yiq) * (yiq * c);
  mat3 outer = outerProduct(vec3(1.0, 0.5, 0.25), vec3(0.2, 0.4, 0.8));
  mat3 diagonal = matrixCompMult(outer, mat3(1.0));  // only the diagonal survives
  mat4 affine = mat4(1.0);
  affine[3] = vec4(0.1, 0.05, -0.1, 1.0);  // a translation column
  affine[0][0] *= 1.0;
  vec3 moved = (affine * vec4(roundTrip, 1.0)).xyz;
  mat3 upper = mat3(affine);  // the top-left 3x3 of a mat4
  mat2 corner = mat2(upper);
  mat3 widened = mat3(corner);  // a mat2 widened with the identity
  bool ok = abs(determinant(turn) - 1.0) < 1e-4 &&
            abs(determinant(yiq) - determinant(transpose(yiq))) < 1e-4 &&
            abs(diagonal[1][1] - 0.2) < 1e-6 && diagonal[0][1] == 0.0 && widened[2] == vec3(0, 0, 1) &&
            distance(roundTrip, c) < 1e-3 && abs(back.x - dot(c, lift[0])) < 1e-5 && square[2][2] == 0.5;
  if (!ok) return kWrong;
  float checker = mod(floor(q.x) + floor(q.y), 2.0);
  return moved * (0.6 + 0.4 * checker) + 0.1 * (upper * vec3(1.0));
}

// ---- Band 5: vector relations and bvecs, mix selecting by a bvec, swizzles read, written and repeated,
// conversions between bool, int, uint and float vectors.
vec3 relationBand(vec2 pixel) {
  vec2 f = fract(pixel / 24.0);
  bvec2 low = lessThan(f, vec2(0.5));
  bvec2 high = greaterThanEqual(f, vec2(0.8));
  bool checker = low.x != low.y;
  bvec3 mask = bvec3(checker, any(high), all(not(low)));
  vec3 c = mix(vec3(0.15, 0.2, 0.3), vec3(0.9, 0.75, 0.3), mask);  // a bvec picks per component
  ivec2 cell = ivec2(pixel) / 24;
  if (all(equal(cell % 5, ivec2(2, 1)))) c = vec3(0.9, 0.2, 0.1);
  if (any(notEqual(cell % 7, ivec2(3, 0))) == false) c = vec3(0.1, 0.8, 0.3);
  bvec4 ordered = bvec4(lessThanEqual(vec2(1.0), vec2(1.0, 2.0)), greaterThan(uvec2(3u, 4u), uvec2(2u)));
  bool conversions = float(true) == 1.0 && int(2.7) == 2 && !bool(0) && uint(3.9) == 3u &&
                     vec3(ivec3(1, 2, 3)) == vec3(1, 2, 3) && ivec2(vec2(-1.5, 1.5)) == ivec2(-1, 1) &&
                     bvec2(vec2(0.0, 2.0)) == bvec2(false, true);
  vec4 v = vec4(c, 1.0);
  v.zx = v.xz;  // swap red and blue: the right side is read before the write
  v.g *= 0.9;
  v.stp = v.stp.xyz;
  vec4 repeated = v.xxyy;
  if (!all(ordered) || !conversions || repeated.y != v.r || repeated.w != v.g) return kWrong;
  return v.rgb;
}

// ---- Band 6: in / out / inout parameters, pre and post ++ and --, every compound assignment, the comma
// operator, ternary, unary + - ! ~, logical && || ^^, a global written by a function.
void split(in float v, out int whole, out float part) {
  whole = int(floor(v));
  part = v - floor(v);
}

void accumulate(inout vec3 sum, in vec3 add, inout int count) {
  sum += add;
  count++;
  gCalls++;
}

vec3 operatorBand(vec2 pixel) {
  int whole;
  float part;
  split(pixel.x / 32.0, whole, part);
  int i = whole, j = whole;
  int a = i++;  // whole; i = whole + 1
  int b = ++j;  // whole + 1; j = whole + 1
  int c = i--;  // whole + 1; i = whole
  int d = --j;  // whole; j = whole
  vec3 sum = vec3(0.0);
  int count = 0;
  for (int k = 0, m = 6; k < m; k++, m--) accumulate(sum, vec3(0.05, 0.03, 0.02) * float(k + 1), count);
  float w = 1.0;
  w += 2.0;
  w -= 0.5;
  w *= 2.0;
  w /= 5.0;  // ((1 + 2 - 0.5) * 2) / 5 = 1
  int bits = whole + 3;
  bits <<= 2;
  bits >>= 1;
  bits |= 1;
  bits &= 0x1F;
  bits ^= 0x5;
  bits %= 11;
  float comma = (w += 1.0, w * 0.5);  // w = 2, comma = 1
  bool ok = a + d == 2 * whole && b + c == 2 * whole + 2 && i == whole && j == whole && count == 3 &&
            gCalls == 3 && !(comma != 1.0) && (true ^^ (count == 3)) == false && (~bits & bits) == 0 &&
            -(+bits) == bits * -1 && (count > 5 || count <= 3) && bits >= 0 && bits < 11;
  if (!ok) return kWrong;
  vec3 base = whole % 2 == 0 ? vec3(0.2, 0.55, 0.35) : vec3(0.25, 0.35, 0.6);
  vec3 col = base * (0.4 + 0.6 * part) + sum;
  col.r += float(bits) / 14.0;
  return col;
}

// ---- Band 7: macros with arguments, the branch #if chose, const arrays, precision qualifiers.
vec3 preprocessorBand(vec2 p) {
  float stripe = floor(p.x * float(STRIPES));
  mediump float t = CURVE(fract(p.x * float(STRIPES)));
  vec3 col = LERP3(vec3(0.1, 0.3, 0.8), vec3(0.9, 0.9, 1.0), t);
  lowp float dim = mod(stripe, 2.0) == 0.0 ? 1.0 : 0.7;
  highp float weighted = 0.0;
  for (int i = 0; i < kWeights.length(); ++i) weighted += kWeights[i] * float(i + 1);  // 0.1+0.4+0.9+1.6
  if (STRIPES != 12 || SQUARE(3) != 9 || abs(weighted - 3.0) > 1e-5 || twice(0.5) != 1.0) return kWrong;
  col *= dim * weighted / 3.0;
  col.g *= 0.7 + 0.3 * p.y;
  return twice(col) * 0.5 + 0.1 * luma(vec4(col, 1.0));
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  float bandHeight = iResolution.y / float(BANDS);
  int band = int(fragCoord.y / bandHeight);
  vec2 local = vec2(fragCoord.x, fragCoord.y - float(band) * bandHeight);  // pixels within the band
  vec2 size = vec2(iResolution.x, bandHeight);
  vec2 p = local / size;  // 0..1 within the band
  vec3 col;
  switch (band) {
    case 0: col = gradientBand(p); break;
    case 1: col = bitsBand(ivec2(local)); break;
    case 2: col = switchBand(p); break;
    case 3: col = loopBand(p); break;
    case 4: col = matrixBand(local, size); break;
    case 5: col = relationBand(local); break;
    case 6: col = operatorBand(local); break;
    default: col = preprocessorBand(p); break;
  }
  if (local.y < 1.0) col *= 0.2;  // a dark line between bands
  fragColor = vec4(clamp(col, 0.0, 1.0), 1.0);
}
