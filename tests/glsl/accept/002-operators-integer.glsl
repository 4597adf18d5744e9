// exercises: 5.1 integer operators on int/ivec/uint/uvec: + - * / %, bitwise & | ^ ~, shifts (vector by scalar, vector by vector, int by uint), compound forms, ++/--
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    int i = int(fragCoord.x), j = iFrame + 3;
    ivec2 iv = ivec2(fragCoord), jv = ivec2(3, 5);
    uint u = uint(fragCoord.y), w = 7u;
    uvec3 uv = uvec3(u, w, 0xFFu), wv = uvec3(1u, 2u, 3u);
    int a = i + j - i * j / (j | 1) % 7;
    ivec2 b = iv + jv - iv * jv / ivec2(2) % jv;
    ivec2 c = iv * 2 + 3 - jv / 2 % 3;
    uint d = u + w - u * w / 3u % 5u;
    uvec3 e = uv * wv + 1u - (uv / 2u) % wv;
    int bits = (i & 0xF0) | (j ^ 0x0F) | ~a;
    ivec2 bv = (iv & jv) | (iv ^ 3) | ~jv & ivec2(0x7fffffff);
    uint ubits = (u & w) | (u ^ 0xFFFFFFFFu) | ~w;
    uvec3 ubv = (uv & wv) | (uv ^ 1u) | ~wv;
    int s1 = i << 2, s2 = j >> 1, s3 = i << 1u;
    ivec2 s4 = iv << 1, s5 = iv >> jv, s6 = iv << uvec2(1u, 2u);
    uint s7 = u << 3, s8 = w >> 1u;
    uvec3 s9 = uv >> wv, s10 = uv << 2;
    a += 1; a -= 2; a *= 3; a /= 2; a %= 5;
    a &= 0xFF; a |= 1; a ^= 2; a <<= 1; a >>= 2;
    iv += 1; iv -= jv; iv *= 2; iv /= jv; iv %= 3; iv &= 7; iv |= jv; iv ^= 1; iv <<= 1; iv >>= jv;
    u += 1u; u -= 1u; u *= 2u; u /= 2u; u %= 3u; u &= 0x7u; u |= 8u; u ^= 1u; u <<= 2; u >>= 1u;
    uv <<= 1u; uv >>= wv; uv %= 5u;
    i++; ++i; j--; --j; u++; --u; iv++; --uv;
    int neg = -i + +j;
    ivec2 negv = -iv;
    float sum = float(a + bits + s1 + s2 + s3 + neg + i + j) + float(d + ubits + s7 + s8 + u)
              + vec2(b + c + bv + s4 + s5 + s6 + negv + iv).x + vec3(e + ubv + s9 + s10 + uv).y;
    fragColor = vec4(fract(sum / 97.0));
}
