// exercises: 4.3.3 built-in function calls with constant arguments are constant expressions, usable as const initialisers and array sizes (the ones glslang folds; see glslang-differs/const-*)
const float A = sin(0.5) + cos(0.5) + tan(0.1) + asin(0.5) + acos(0.5) + atan(1.0, 2.0) + radians(90.0) + degrees(1.0);
const float B = pow(2.0, 3.0) + exp(1.0) + log(2.0) + exp2(3.0) + log2(8.0) + sqrt(4.0) + inversesqrt(4.0);
const vec3 C = abs(vec3(-1.0)) + floor(vec3(1.5)) + ceil(vec3(1.5)) + fract(vec3(1.5)) + mix(vec3(0.0), vec3(1.0), 0.5) + smoothstep(0.0, 1.0, vec3(0.5));
const float D = length(vec3(1.0, 2.0, 2.0)) + distance(vec2(0.0), vec2(3.0, 4.0)) + dot(vec2(1.0), vec2(2.0));
const vec3 E = normalize(cross(vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0))) + reflect(vec3(1.0, -1.0, 0.0), vec3(0.0, 1.0, 0.0));
const mat2 F = outerProduct(vec2(1.0), vec2(2.0)) * mat2(0.5);
const float G = faceforward(vec2(1.0), vec2(1.0), vec2(-1.0)).x + refract(vec2(1.0, 0.0), vec2(0.0, 1.0), 0.5).y;
const bvec3 H = lessThan(vec3(1.0), vec3(2.0));
const int I = int(max(3.0, 2.0)) + clamp(-5, 0, 3) + abs(-2) + min(7, 4);
const uint J = max(3u, 9u);
float table[int(sqrt(16.0)) + I];
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    table[0] = A + B;
    fragColor = vec4(fract(table[0] + C.x + D + E.y + F[1][0] + G), all(H) ? 1.0 : 0.0, float(table.length() + int(J)) * 0.01, 1.0);
}
